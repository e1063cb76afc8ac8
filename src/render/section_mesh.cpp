// The 2D section of the water, meshed and extruded across the fall (see section_mesh.hpp).
#include "render/section_mesh.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mistfall {

namespace {

// Disc radius beyond which the distance is clamped: the smoothing reads 1 cell per pass around the surface.
constexpr double kReach = 2.0;  // [l0] past the disc

void smooth(std::vector<float>& phi, int nx, int ny) {
  std::vector<float> tmp(phi.size());
  for (int j = 0; j < ny; ++j)  // along x
    for (int i = 0; i < nx; ++i) {
      const std::size_t c = static_cast<std::size_t>(j) * nx + i;
      const float l = phi[i > 0 ? c - 1 : c], r = phi[i + 1 < nx ? c + 1 : c];
      tmp[c] = 0.25f * l + 0.5f * phi[c] + 0.25f * r;
    }
  for (int j = 0; j < ny; ++j)  // along y
    for (int i = 0; i < nx; ++i) {
      const std::size_t c = static_cast<std::size_t>(j) * nx + i;
      const float d = tmp[j > 0 ? c - nx : c], u = tmp[j + 1 < ny ? c + nx : c];
      phi[c] = 0.25f * d + 0.5f * tmp[c] + 0.25f * u;
    }
}

// Enclosed outside regions (phi >= 0 not connected to the grid's border) smaller than max_nodes become water.
void fillPockets(SectionField& f, std::size_t max_nodes) {
  const std::size_t n = f.phi.size();
  std::vector<int> label(n, -1);  // -1 unvisited outside or inside; 0 open air; k > 0 pocket k
  std::vector<std::size_t> stack;
  auto flood = [&](std::size_t seed, int id, std::vector<std::size_t>* members) {
    stack.assign(1, seed);
    label[seed] = id;
    while (!stack.empty()) {
      const std::size_t c = stack.back();
      stack.pop_back();
      if (members) members->push_back(c);
      const int i = static_cast<int>(c % f.nx), j = static_cast<int>(c / f.nx);
      const int di[4] = {-1, 1, 0, 0}, dj[4] = {0, 0, -1, 1};
      for (int k = 0; k < 4; ++k) {
        const int a = i + di[k], b = j + dj[k];
        if (a < 0 || b < 0 || a >= f.nx || b >= f.ny) continue;
        const std::size_t m = static_cast<std::size_t>(b) * f.nx + a;
        if (label[m] == -1 && f.phi[m] >= 0.0f) label[m] = id, stack.push_back(m);
      }
    }
  };
  for (int i = 0; i < f.nx; ++i)
    for (int j : {0, f.ny - 1})
      if (const std::size_t c = static_cast<std::size_t>(j) * f.nx + i; label[c] == -1 && f.phi[c] >= 0.0f)
        flood(c, 0, nullptr);
  for (int j = 0; j < f.ny; ++j)
    for (int i : {0, f.nx - 1})
      if (const std::size_t c = static_cast<std::size_t>(j) * f.nx + i; label[c] == -1 && f.phi[c] >= 0.0f)
        flood(c, 0, nullptr);
  std::vector<std::size_t> members;
  int id = 1;
  for (std::size_t c = 0; c < n; ++c) {
    if (label[c] != -1 || f.phi[c] < 0.0f) continue;
    members.clear();
    flood(c, id++, &members);
    if (members.size() > max_nodes) continue;
    for (std::size_t m : members) f.phi[m] = -0.5f * static_cast<float>(f.h), f.pocket[m] = 1;
  }
}

std::uint64_t hash3(std::int64_t x, std::int64_t y, std::int64_t z) {
  std::uint64_t h = static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull ^
                    static_cast<std::uint64_t>(y) * 0xC2B2AE3D27D4EB4Full ^
                    static_cast<std::uint64_t>(z) * 0x165667B19E3779F9ull;
  h ^= h >> 31, h *= 0xBF58476D1CE4E5B9ull, h ^= h >> 27, h *= 0x94D049BB133111EBull, h ^= h >> 31;
  return h;
}

}  // namespace

double valueNoise(double x, double y, double z) {
  const double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
  const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy),
             iz = static_cast<std::int64_t>(fz);
  auto s = [](double t) { return t * t * (3.0 - 2.0 * t); };
  const double tx = s(x - fx), ty = s(y - fy), tz = s(z - fz);
  auto v = [&](int a, int b, int c) {
    return static_cast<double>(hash3(ix + a, iy + b, iz + c) >> 11) * 0x1.0p-53 * 2.0 - 1.0;
  };
  auto lerp = [](double a, double b, double t) { return a + (b - a) * t; };
  return lerp(lerp(lerp(v(0, 0, 0), v(1, 0, 0), tx), lerp(v(0, 1, 0), v(1, 1, 0), tx), ty),
              lerp(lerp(v(0, 0, 1), v(1, 0, 1), tx), lerp(v(0, 1, 1), v(1, 1, 1), tx), ty), tz);
}

SectionField sectionField(const std::vector<Vec<2>>& centres, const SectionParameters& p,
                          const std::vector<SectionLink>& links) {
  const double l0 = p.spacing;
  if (!(l0 > 0.0)) throw std::invalid_argument("sectionField: particle spacing must be > 0");
  SectionField f;
  f.h = p.cell_fraction * l0;
  if (centres.empty() && links.empty()) return f;
  Vec<2> lo = centres.empty() ? links.front().a : centres.front(), hi = lo;
  for (const auto& c : centres) lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
  for (const auto& l : links) lo = lo.cwiseMin(l.a).cwiseMin(l.b), hi = hi.cwiseMax(l.a).cwiseMax(l.b);
  const double margin = (p.radius + kReach) * l0 + 2.0 * f.h;
  f.origin = lo - Vec<2>::Constant(margin);
  f.nx = static_cast<int>(std::ceil((hi.x() - lo.x() + 2.0 * margin) / f.h)) + 1;
  f.ny = static_cast<int>(std::ceil((hi.y() - lo.y() + 2.0 * margin) / f.h)) + 1;
  const double radius = p.radius * l0, reach = kReach * l0;
  f.phi.assign(static_cast<std::size_t>(f.nx) * f.ny, static_cast<float>(reach));
  f.pocket.assign(f.phi.size(), 0);
  const int span = static_cast<int>(std::ceil((radius + reach) / f.h));
  for (const auto& c : centres) {
    const int ci = static_cast<int>(std::lround((c.x() - f.origin.x()) / f.h));
    const int cj = static_cast<int>(std::lround((c.y() - f.origin.y()) / f.h));
    for (int j = std::max(0, cj - span); j <= std::min(f.ny - 1, cj + span); ++j)
      for (int i = std::max(0, ci - span); i <= std::min(f.nx - 1, ci + span); ++i) {
        const double dx = f.origin.x() + i * f.h - c.x(), dy = f.origin.y() + j * f.h - c.y();
        float& v = f.phi[static_cast<std::size_t>(j) * f.nx + i];
        v = std::min(v, static_cast<float>(std::sqrt(dx * dx + dy * dy) - radius));
      }
  }
  // A capsule's distance field is smooth already: it is widened by what the smoothing (about 0.8 of the blur's
  // standard deviation, sqrt(passes / 2) cells) and the erosion take from a thin feature, so it keeps its radius.
  const double link_extra = p.erosion * l0 + 0.8 * std::sqrt(0.5 * p.smoothing_passes) * f.h;
  for (const SectionLink& link : links) {
    const double link_radius = link.radius + link_extra;
    const Vec<2> lo_corner = link.a.cwiseMin(link.b) - Vec<2>::Constant(link.radius + reach);
    const Vec<2> hi_corner = link.a.cwiseMax(link.b) + Vec<2>::Constant(link.radius + reach);
    const Vec<2> d = link.b - link.a;
    const double len2 = d.squaredNorm();
    for (int j = std::max(0, static_cast<int>((lo_corner.y() - f.origin.y()) / f.h));
         j <= std::min(f.ny - 1, static_cast<int>((hi_corner.y() - f.origin.y()) / f.h) + 1); ++j)
      for (int i = std::max(0, static_cast<int>((lo_corner.x() - f.origin.x()) / f.h));
           i <= std::min(f.nx - 1, static_cast<int>((hi_corner.x() - f.origin.x()) / f.h) + 1); ++i) {
        const Vec<2> q(f.origin.x() + i * f.h, f.origin.y() + j * f.h);
        const double t = len2 > 0.0 ? std::clamp((q - link.a).dot(d) / len2, 0.0, 1.0) : 0.0;
        float& v = f.phi[static_cast<std::size_t>(j) * f.nx + i];
        v = std::min(v, static_cast<float>((q - link.a - t * d).norm() - link_radius));
      }
  }
  for (int s = 0; s < p.smoothing_passes; ++s) smooth(f.phi, f.nx, f.ny);
  for (float& v : f.phi) v += static_cast<float>(p.erosion * l0);
  for (float& v : f.phi)  // no node exactly on the surface: crossings never coincide with nodes
    if (std::abs(v) < 1e-6f * f.h) v = 1e-6f * static_cast<float>(f.h);
  fillPockets(f, static_cast<std::size_t>(p.pocket_area * l0 * l0 / (f.h * f.h)));
  return f;
}

SectionMesh marchingSquares(const SectionField& f) {
  SectionMesh m;
  if (f.nx < 2 || f.ny < 2) return m;
  const std::size_t nodes = static_cast<std::size_t>(f.nx) * f.ny;
  std::vector<int> node_id(nodes, -1), hx(nodes, -1), vy(nodes, -1);  // crossing on edge to (i+1, j) / (i, j+1)
  auto node = [&](int i, int j) -> std::size_t { return static_cast<std::size_t>(j) * f.nx + i; };
  auto inside = [&](int i, int j) { return f.phi[node(i, j)] < 0.0f; };
  auto position = [&](int i, int j) { return Vec<2>(f.origin.x() + i * f.h, f.origin.y() + j * f.h); };
  auto cornerVertex = [&](int i, int j) {
    int& id = node_id[node(i, j)];
    if (id < 0) id = static_cast<int>(m.vertices.size()), m.vertices.push_back(position(i, j));
    return id;
  };
  // The crossing on the edge from node a to node b (b is a's right or upper neighbour).
  auto crossing = [&](int ia, int ja, int ib, int jb) {
    int& id = (jb == ja ? hx : vy)[node(ia, ja)];
    if (id < 0) {
      const double pa = f.at(ia, ja), pb = f.at(ib, jb), t = pa / (pa - pb);
      id = static_cast<int>(m.vertices.size());
      m.vertices.push_back(position(ia, ja) + t * (position(ib, jb) - position(ia, ja)));
    }
    return id;
  };
  struct Corner {
    int id;
    bool is_crossing;
  };
  std::vector<Corner> poly;
  for (int j = 0; j + 1 < f.ny; ++j)
    for (int i = 0; i + 1 < f.nx; ++i) {
      const int ci[4] = {i, i + 1, i + 1, i}, cj[4] = {j, j, j + 1, j + 1};
      bool in[4];
      int count = 0;
      for (int k = 0; k < 4; ++k) count += (in[k] = inside(ci[k], cj[k]));
      if (count == 0) continue;
      poly.clear();
      for (int k = 0; k < 4; ++k) {
        const int n = (k + 1) % 4;
        if (in[k]) poly.push_back({cornerVertex(ci[k], cj[k]), false});
        if (in[k] != in[n]) {  // edges are stored from the lower-left node
          const bool forward = (k < 2);
          poly.push_back({forward ? crossing(ci[k], cj[k], ci[n], cj[n]) : crossing(ci[n], cj[n], ci[k], cj[k]),
                          true});
        }
      }
      const bool saddle = count == 2 && in[0] == in[2];
      const double centre = 0.25 * (f.at(i, j) + f.at(i + 1, j) + f.at(i + 1, j + 1) + f.at(i, j + 1));
      if (saddle && centre >= 0.0) {  // two separate corners: a triangle around each
        const int n = static_cast<int>(poly.size());
        for (int k = 0; k < n; ++k) {
          if (poly[k].is_crossing) continue;
          const int before = poly[(k + n - 1) % n].id, after = poly[(k + 1) % n].id;
          m.triangles.push_back({before, poly[k].id, after});
          m.outline.push_back({after, before});
        }
        continue;
      }
      const int n = static_cast<int>(poly.size());
      for (int k = 1; k + 1 < n; ++k) m.triangles.push_back({poly[0].id, poly[k].id, poly[k + 1].id});
      for (int k = 0; k < n; ++k)
        if (poly[k].is_crossing && poly[(k + 1) % n].is_crossing)
          m.outline.push_back({poly[k].id, poly[(k + 1) % n].id});
    }
  return m;
}

double sectionArea(const SectionMesh& s) {
  double a = 0.0;
  for (const auto& t : s.triangles) {
    const Vec<2> u = s.vertices[t[1]] - s.vertices[t[0]], v = s.vertices[t[2]] - s.vertices[t[0]];
    a += 0.5 * (u.x() * v.y() - u.y() * v.x());
  }
  return a;
}

TriangleMesh extrudeSection(const SectionMesh& s, const ExtrusionParameters& p) {
  if (!(p.width > 0.0)) throw std::invalid_argument("extrudeSection: width must be > 0");
  TriangleMesh mesh;
  const int nv = static_cast<int>(s.vertices.size());
  if (nv == 0) return mesh;
  const int rings = std::max(3, p.rings);
  const double half = 0.5 * p.width, bevel = std::min(p.bevel, p.width / rings);
  std::vector<double> z(rings + 1);
  z[0] = -half, z[rings] = half, z[1] = -half + bevel, z[rings - 1] = half - bevel;
  for (int k = 2; k < rings - 1; ++k) z[k] = z[1] + (z[rings - 1] - z[1]) * (k - 1) / (rings - 2);

  // Outline vertices and their normals in the section (sum of the adjacent segments' right-hand normals).
  std::vector<int> slot(nv, -1);
  std::vector<int> outline_vertices;
  std::vector<Vec<2>> normal2;
  for (const auto& e : s.outline) {
    const Vec<2> d = s.vertices[e[1]] - s.vertices[e[0]];
    const Vec<2> n(d.y(), -d.x());
    for (int v : e) {
      if (slot[v] < 0) slot[v] = static_cast<int>(outline_vertices.size()), outline_vertices.push_back(v),
                       normal2.push_back(Vec<2>::Zero());
      normal2[slot[v]] += n;
    }
  }
  for (auto& n : normal2) n = n.norm() > 0.0 ? Vec<2>(n.normalized()) : Vec<2>(0.0, 1.0);
  const int no = static_cast<int>(outline_vertices.size());
  auto displaced = [&](int o, double zk) {
    const Vec<2>& v = s.vertices[outline_vertices[o]];
    const double L = p.variation_length;
    const double d = p.variation * valueNoise(v.x() / L, (v.y() + p.drift_speed * p.time) / L, 4.0 * zk / L);
    const Vec<2> q = v + d * normal2[o];
    return Vec<3>(q.x(), q.y(), zk);
  };
  // Vertices: caps first (bottom then top), then rings 1 .. rings-1 of the outline.
  for (int cap = 0; cap < 2; ++cap)
    for (int v = 0; v < nv; ++v)
      mesh.vertices.push_back(slot[v] >= 0 ? displaced(slot[v], cap ? half : -half)
                                           : Vec<3>(s.vertices[v].x(), s.vertices[v].y(), cap ? half : -half));
  for (int k = 1; k < rings; ++k)
    for (int o = 0; o < no; ++o) mesh.vertices.push_back(displaced(o, z[k]));
  auto ringVertex = [&](int k, int o) {
    if (k == 0) return outline_vertices[o];
    if (k == rings) return nv + outline_vertices[o];
    return 2 * nv + (k - 1) * no + o;
  };
  for (const auto& t : s.triangles) {
    mesh.triangles.push_back({t[0], t[2], t[1]});                // bottom cap faces -z
    mesh.triangles.push_back({nv + t[0], nv + t[1], nv + t[2]});  // top cap faces +z
  }
  mesh.normals.assign(mesh.vertices.size(), Vec<3>::Zero());
  for (const auto& e : s.outline)
    for (int k = 0; k < rings; ++k) {
      const int a0 = ringVertex(k, slot[e[0]]), b0 = ringVertex(k, slot[e[1]]);
      const int a1 = ringVertex(k + 1, slot[e[0]]), b1 = ringVertex(k + 1, slot[e[1]]);
      for (const std::array<int, 3>& t : {std::array<int, 3>{a0, b0, b1}, std::array<int, 3>{a0, b1, a1}}) {
        mesh.triangles.push_back(t);
        const Vec<3>& a = mesh.vertices[t[0]];
        const Vec<3> n = (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a);
        for (int v : t) mesh.normals[v] += n;
      }
    }
  for (int v = 0; v < 2 * nv; ++v) {  // caps: +-z, leaning halfway out on the rim
    const Vec<3> axis(0.0, 0.0, v < nv ? -1.0 : 1.0);
    Vec<3>& n = mesh.normals[v];
    n = n.norm() > 0.0 ? Vec<3>(n.normalized() + axis) : axis;
  }
  for (auto& n : mesh.normals) n = n.norm() > 0.0 ? Vec<3>(n.normalized()) : Vec<3>(0.0, 1.0, 0.0);
  return mesh;
}

}  // namespace mistfall
