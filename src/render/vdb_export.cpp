// OpenVDB files of the render stage's volumes (see vdb_export.hpp).
#include "render/vdb_export.hpp"

#include <openvdb/openvdb.h>

#include <algorithm>
#include <mutex>
#include <stdexcept>

namespace mistfall {

namespace {

void initialise() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

openvdb::math::Transform::Ptr transformOf(const DensityGrid& g) {
  auto t = openvdb::math::Transform::createLinearTransform(g.h);
  t->postTranslate(openvdb::Vec3d(g.origin.x() + 0.5 * g.h, g.origin.y() + 0.5 * g.h, g.origin.z() + 0.5 * g.h));
  return t;
}

}  // namespace

void writeVdb(const std::filesystem::path& file, const std::vector<std::pair<std::string, const DensityGrid*>>& grids) {
  initialise();
  openvdb::GridPtrVec out;
  for (const auto& [name, g] : grids) {
    auto grid = openvdb::FloatGrid::create(0.0f);
    grid->setName(name);
    grid->setGridClass(openvdb::GRID_FOG_VOLUME);
    grid->setTransform(transformOf(*g));
    auto acc = grid->getAccessor();
    for (int k = 0; k < g->n[2]; ++k)
      for (int j = 0; j < g->n[1]; ++j)
        for (int i = 0; i < g->n[0]; ++i)
          if (const float v = g->at(i, j, k); v > 0.0f) acc.setValue(openvdb::Coord(i, j, k), v);
    out.push_back(grid);
  }
  const std::filesystem::path tmp = file.string() + ".tmp";
  try {
    openvdb::io::File f(tmp.string());
    f.write(out);
    f.close();
    std::filesystem::rename(tmp, file);
  } catch (const std::exception& e) {
    std::filesystem::remove(tmp);
    throw std::runtime_error("cannot write " + file.string() + ": " + e.what());
  }
}

DensityGrid readVdbGrid(const std::filesystem::path& file, const std::string& name, const DensityGrid& like) {
  initialise();
  openvdb::io::File f(file.string());
  f.open();
  openvdb::FloatGrid::Ptr grid;
  if (f.hasGrid(name)) grid = openvdb::gridPtrCast<openvdb::FloatGrid>(f.readGrid(name));
  f.close();
  if (!grid) throw std::runtime_error(file.string() + ": no float grid '" + name + "'");
  DensityGrid g = like;
  std::fill(g.value.begin(), g.value.end(), 0.0f);
  auto acc = grid->getConstAccessor();
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) g.at(i, j, k) = acc.getValue(openvdb::Coord(i, j, k));
  return g;
}

}  // namespace mistfall
