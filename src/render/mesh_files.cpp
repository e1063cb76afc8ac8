// POV-Ray mesh2 and PLY files of a triangle mesh (see mesh_files.hpp).
#include "render/mesh_files.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace mistfall {

namespace {

void writeVector(std::ostream& out, const Vec<3>& v) { out << '<' << v.x() << ',' << v.y() << ',' << v.z() << '>'; }

template <class T>
void putLe(std::ostream& out, T v) {  // the build targets little-endian machines (as the VTK writer)
  char bytes[sizeof(T)];
  std::memcpy(bytes, &v, sizeof(T));
  out.write(bytes, sizeof(T));
}

template <class T>
T getLe(std::istream& in) {
  T v;
  char bytes[sizeof(T)];
  in.read(bytes, sizeof(T));
  std::memcpy(&v, bytes, sizeof(T));
  return v;
}

}  // namespace

void writePovMesh(const std::filesystem::path& file, const TriangleMesh& mesh, const std::string& name) {
  writeFileAtomically(file, [&](std::ostream& out) {
    out.precision(7);  // 0.1 um at 1 m
    out << "// Water surface written by mistfall render: " << mesh.vertices.size() << " vertices, "
        << mesh.triangles.size() << " triangles\n#declare " << name << " = mesh2 {\n  vertex_vectors { "
        << mesh.vertices.size();
    for (const auto& v : mesh.vertices) out << ",\n    ", writeVector(out, v);
    out << "\n  }\n  normal_vectors { " << mesh.normals.size();
    for (const auto& n : mesh.normals) out << ",\n    ", writeVector(out, n);
    out << "\n  }\n  face_indices { " << mesh.triangles.size();
    for (const auto& t : mesh.triangles) out << ",\n    <" << t[0] << ',' << t[1] << ',' << t[2] << '>';
    out << "\n  }\n  inside_vector <0.31, 0.57, 0.76>\n}\n";
  });
}

void writePly(const std::filesystem::path& file, const TriangleMesh& mesh) {
  writeFileAtomically(file, [&](std::ostream& out) {
    out << "ply\nformat binary_little_endian 1.0\ncomment mistfall water surface\nelement vertex "
        << mesh.vertices.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\n"
           "property float nz\nelement face "
        << mesh.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
      for (const Vec<3>* v : {&mesh.vertices[i], &mesh.normals[i]})
        for (int k = 0; k < 3; ++k) putLe<float>(out, static_cast<float>((*v)[k]));
    for (const auto& t : mesh.triangles) {
      putLe<std::uint8_t>(out, 3);
      for (int v : t) putLe<std::int32_t>(out, v);
    }
  });
}

TriangleMesh readPly(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ": cannot open PLY file");
  std::string line;
  std::size_t vertices = 0, faces = 0;
  bool binary = false;
  while (std::getline(in, line) && line != "end_header") {
    if (line == "format binary_little_endian 1.0") binary = true;
    if (line.rfind("element vertex ", 0) == 0) vertices = std::stoul(line.substr(15));
    if (line.rfind("element face ", 0) == 0) faces = std::stoul(line.substr(13));
  }
  if (!binary || line != "end_header") throw std::runtime_error(file.string() + ": not a PLY file of mistfall");
  TriangleMesh mesh;
  for (std::size_t i = 0; i < vertices; ++i) {
    Vec<3> v, n;
    for (int k = 0; k < 3; ++k) v[k] = getLe<float>(in);
    for (int k = 0; k < 3; ++k) n[k] = getLe<float>(in);
    mesh.vertices.push_back(v);
    mesh.normals.push_back(n);
  }
  for (std::size_t i = 0; i < faces; ++i) {
    if (getLe<std::uint8_t>(in) != 3) throw std::runtime_error(file.string() + ": a face is not a triangle");
    std::array<int, 3> t;
    for (int& v : t) v = getLe<std::int32_t>(in);
    mesh.triangles.push_back(t);
  }
  if (!in) throw std::runtime_error(file.string() + ": PLY file is truncated");
  return mesh;
}

}  // namespace mistfall
