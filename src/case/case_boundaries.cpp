// The [[inflow]] and [[outflow]] tables of a case file (open boundaries, mps/open_boundaries.hpp):
//   [[inflow]]  name, min, max (the buffer box), direction (a unit coordinate vector, e.g. [1, 0]),
//               discharge (q > 0 [m^2/s]): the buffer's water is driven at U = q / depth along direction,
//               depth = the box's extent along the axis of gravity; pressure ("solved" or "harmonic": the
//               buffer's pressure, mps/inflow_pressure.hpp).
//   [[outflow]] name, min, max: fluid entering the box is removed.
//   [[vent]]    name, min, max (the opening, cut through a wall), direction (outward, a unit coordinate vector):
//               the air's opening to the ambient (mps/gas_vent.hpp).
// Checks: boxes well formed and inside the domain, holding lattice points; the flow axis not the gravity axis;
// an inflow box overlaps no wall region and no other inflow or outflow box; a vent box overlaps no wall region and no
// inflow, outflow or other vent box, and the case has gas.
#include <algorithm>
#include <cmath>
#include <string>

#include "case/case_file.hpp"
#include "case/scene.hpp"
#include "case/toml_reader.hpp"

namespace mistfall::detail {
namespace {

std::string num(double v) { return formatNumber(v); }

bool overlap(const Box& a, const Box& b, int dim) {
  for (int k = 0; k < dim; ++k)
    if (std::min(a.max[k], b.max[k]) <= std::max(a.min[k], b.min[k])) return false;
  return true;
}

// The axis along which gravity acts most (the vertical).
int verticalAxis(const CaseConfig& c) {
  int axis = 0;
  for (int k = 1; k < c.dimension; ++k)
    if (std::abs(c.physics.gravity[k]) > std::abs(c.physics.gravity[axis])) axis = k;
  return axis;
}

void readBox(const Reader& rd, const toml::table& t, const std::string& p, const CaseConfig& c, Box& box) {
  rd.vector(t, p, "min", c.dimension, box.min, true);
  rd.vector(t, p, "max", c.dimension, box.max, true);
  for (int k = 0; k < c.dimension; ++k) {
    if (!(box.min[k] < box.max[k]))
      rd.fail(p + ".min[" + std::to_string(k) + "] = " + num(box.min[k]) + " is not below max[" + std::to_string(k) +
              "] = " + num(box.max[k]) + "; allowed min < max on every axis");
    if (box.min[k] < c.domain.min[k] || box.max[k] > c.domain.max[k])
      rd.fail(p + " [" + num(box.min[k]) + ", " + num(box.max[k]) + "] on axis " + std::to_string(k) +
              " leaves the domain [" + num(c.domain.min[k]) + ", " + num(c.domain.max[k]) + "]; allowed a box inside it");
  }
  if (countLatticePoints(c, box) == 0) rd.fail(p + " holds no lattice point; allowed a box holding at least one");
}

std::string uniqueName(const Reader& rd, const toml::table& t, const std::string& p,
                       const std::vector<std::string>& taken) {
  Field nf = rd.field(t, p, "name");
  if (!nf.node) rd.missing(nf, "a non-empty unique string");
  const std::string name = rd.string(nf, "a non-empty unique string");
  if (name.empty()) rd.fail(nf.path + " = \"\" is empty; allowed a non-empty unique string");
  for (const auto& other : taken)
    if (other == name) rd.fail(nf.path + " = \"" + name + "\" is taken; allowed names unique among boundaries");
  return name;
}

}  // namespace

void readOpenBoundaries(const Reader& rd, const toml::table& root, CaseConfig& c) {
  std::vector<std::string> names;
  std::vector<Box> boxes;
  auto tables = [&](const char* key) -> const toml::array* {
    Field f = rd.field(root, "", key);
    if (!f.node) return nullptr;
    if (!f.node->is_array_of_tables()) rd.wrongType(f, std::string("an array of tables written as [[") + key + "]]");
    return f.node->as_array();
  };
  const int vertical = verticalAxis(c);
  auto unitDirection = [&](const toml::table& t, const std::string& p, int& axis, int& sign) {
    std::array<double, 3> dir{0.0, 0.0, 0.0};
    rd.vector(t, p, "direction", c.dimension, dir, true);
    int nonzero = 0;
    for (int k = 0; k < c.dimension; ++k)
      if (dir[k] != 0.0) ++nonzero, axis = k, sign = dir[k] > 0.0 ? 1 : -1;
    if (nonzero != 1 || std::abs(dir[axis]) != 1.0)
      rd.fail(p + ".direction is not a unit coordinate vector; allowed e.g. [1, 0] or [0, 0, -1]");
  };
  if (const toml::array* a = tables("inflow")) {
    for (std::size_t i = 0; i < a->size(); ++i) {
      const toml::table& t = *(*a)[i].as_table();
      const std::string p = "inflow[" + std::to_string(i) + "]";
      rd.checkKeys(t, p, {"name", "min", "max", "direction", "discharge", "pressure"});
      Inflow in;
      in.name = uniqueName(rd, t, p, names);
      readBox(rd, t, p, c, in.box);
      unitDirection(t, p, in.axis, in.sign);
      if (in.axis == vertical)
        rd.fail(p + ".direction is along gravity; allowed a horizontal direction (the depth is measured along gravity)");
      rd.number(t, p, "discharge", {0.0, 100.0, true, false}, in.discharge, true);
      in.speed = in.discharge / (in.box.max[vertical] - in.box.min[vertical]);
      if (rd.choice(t, p, "pressure", {"solved", "harmonic"}) == 1) in.pressure = Inflow::Pressure::Harmonic;
      for (const Region& r : c.regions)
        if (r.material == Material::Wall && overlap(r.box, in.box, c.dimension))
          rd.fail(p + " overlaps wall region \"" + r.name + "\"; allowed an inflow box clear of walls");
      names.push_back(in.name);
      boxes.push_back(in.box);
      c.inflows.push_back(in);
    }
  }
  if (const toml::array* a = tables("outflow")) {
    for (std::size_t i = 0; i < a->size(); ++i) {
      const toml::table& t = *(*a)[i].as_table();
      const std::string p = "outflow[" + std::to_string(i) + "]";
      rd.checkKeys(t, p, {"name", "min", "max"});
      Outflow out;
      out.name = uniqueName(rd, t, p, names);
      readBox(rd, t, p, c, out.box);
      for (std::size_t j = 0; j < c.inflows.size(); ++j)
        if (overlap(out.box, c.inflows[j].box, c.dimension))
          rd.fail(p + " overlaps inflow \"" + c.inflows[j].name + "\"; allowed an outflow box clear of inflows");
      names.push_back(out.name);
      boxes.push_back(out.box);
      c.outflows.push_back(out);
    }
  }
  if (const toml::array* a = tables("vent")) {
    const bool has_gas =
        std::any_of(c.regions.begin(), c.regions.end(), [](const Region& r) { return r.material == Material::Gas; });
    for (std::size_t i = 0; i < a->size(); ++i) {
      const toml::table& t = *(*a)[i].as_table();
      const std::string p = "vent[" + std::to_string(i) + "]";
      rd.checkKeys(t, p, {"name", "min", "max", "direction", "inflow", "liquid_exit"});
      if (!has_gas)
        rd.fail(p + ": a vent opens the air to the ambient, and this case has no gas region; allowed with a "
                    "region of material = \"gas\"");
      Vent v;
      v.name = uniqueName(rd, t, p, names);
      readBox(rd, t, p, c, v.box);
      unitDirection(t, p, v.axis, v.sign);
      if (rd.choice(t, p, "inflow", {"total_pressure", "static"}) == 1) v.inflow = Vent::Inflow::Static;
      if (rd.choice(t, p, "liquid_exit", {"outer_face", "inner_face"}) == 1)
        v.liquid_exit = Vent::LiquidExit::InnerFace;
      for (const Region& r : c.regions)
        if (r.material == Material::Wall && overlap(r.box, v.box, c.dimension))
          rd.fail(p + " overlaps wall region \"" + r.name + "\"; allowed a vent box clear of walls (cut the opening "
                      "out of the wall regions)");
      for (std::size_t j = 0; j < boxes.size(); ++j)
        if (overlap(v.box, boxes[j], c.dimension))
          rd.fail(p + " overlaps boundary \"" + names[j] + "\"; allowed a vent box clear of inflows, outflows and "
                      "other vents");
      names.push_back(v.name);
      boxes.push_back(v.box);
      c.vents.push_back(v);
    }
  }
}

}  // namespace mistfall::detail
