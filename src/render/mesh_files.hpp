// The water surface mesh as files (written atomically, io/atomic_file.hpp):
//   POV-Ray: an include file declaring `#declare NAME = mesh2 { vertex_vectors, normal_vectors, face_indices,
//            inside_vector }` in the simulation's coordinates (the scene's camera makes them right-handed).
//   PLY:     binary little-endian, `vertex` (float x y z nx ny nz) and `face` (uchar count, int indices), readable
//            by Blender and ParaView.
#pragma once

#include <filesystem>
#include <string>

#include "render/surface_mesh.hpp"

namespace mistfall {

void writePovMesh(const std::filesystem::path& file, const TriangleMesh& mesh, const std::string& name);
void writePly(const std::filesystem::path& file, const TriangleMesh& mesh);

// Reads a PLY written by writePly (tests, tools). Throws std::runtime_error naming the path on other input.
TriangleMesh readPly(const std::filesystem::path& file);

}  // namespace mistfall
