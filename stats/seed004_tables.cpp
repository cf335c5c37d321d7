#include "stats/seed004_tables.h"

#include <cstdio>

#include "mesh/procedural.h"
#include "mesh/reference_meshes.h"

namespace tessref::stats {
namespace {

std::string printf_string(const char* format, auto... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, format, args...);
  return buf;
}

// "Nagata eps = 0.06" as the paper labels its rows; other schemes by name.
std::string scheme_label(Interpolant s, double eps) {
  if (s != Interpolant::Nagata) return seed004_scheme_name(s);
  return printf_string("Nagata eps = %g", eps);
}

InterpolantParams params_for(double nagata_eps) {
  InterpolantParams p;
  p.phong_alpha = 0.75;
  p.nagata_eps = nagata_eps;
  return p;
}

std::string mean_std(double mean, double spread) { return printf_string("%g ± %g", mean, spread); }
std::string range(double lo, double hi) { return printf_string("[%g, %g]", lo, hi); }

std::string format_scheme_rows(const std::vector<SchemeRow>& rows, const char* title) {
  std::string out = printf_string("%-28s %-32s %s\n", "Name", title, "Min, max");
  for (const SchemeRow& r : rows)
    out += printf_string("%-28s %-32s %s\n", (r.mesh + " " + scheme_label(r.scheme, r.nagata_eps)).c_str(),
                         mean_std(r.value.mean, r.value.std_dev).c_str(),
                         range(r.value.min, r.value.max).c_str());
  return out;
}

}  // namespace

const char* seed004_scheme_name(Interpolant s) {
  switch (s) {
    case Interpolant::Phong: return "Phong";
    case Interpolant::Nagata: return "Nagata";
    case Interpolant::NLSA: return "NLSA";
    case Interpolant::PN: return "PN";
  }
  return "?";
}

std::vector<NamedMesh> seed004_meshes() {
  std::vector<NamedMesh> m;
  m.push_back({"Vase", make_seed004_vase(), 0.06});
  m.push_back({"RoundedCube", make_rounded_cube(), 0.0});
  m.push_back({"Sphere", make_icosphere(2, 1.0f), 0.0});
  m.push_back({"Torus", make_seed004_torus(10), 0.0});
  return m;
}

std::vector<DistanceRow> seed004_table3(const Parallel& parallel) {
  struct Case {
    const char* surface;
    int step;
  };
  static constexpr Case kCases[] = {{"Sphere", 0}, {"Sphere", 1}, {"Sphere", 2}, {"Sphere", 3},
                                    {"Torus", 5},  {"Torus", 10}, {"Torus", 15}, {"Torus", 17},
                                    {"Torus", 19}};
  std::vector<DistanceRow> rows;
  for (const Case& c : kCases) {
    const bool sphere = c.surface[0] == 'S';
    const Mesh mesh = sphere ? make_icosphere(c.step, 1.0f) : make_seed004_torus(c.step);
    for (Interpolant s : kSeed004Schemes) {
      const auto patches = build_patches(mesh, s, params_for(0.0));
      const std::vector<double> d = distance_samples(
          patches, sphere ? AnalyticSurface::UnitSphere : AnalyticSurface::Seed004Torus, kSeed004Segments, parallel);
      rows.push_back({c.surface, c.step, s, summarize(d)});
    }
  }
  return rows;
}

std::vector<MeshRow> seed004_table4() {
  std::vector<MeshRow> rows;
  for (const NamedMesh& m : seed004_meshes()) rows.push_back({m.name, mesh_stats(m.mesh)});
  return rows;
}

MeshReport measure_mesh(const std::string& name, const Mesh& mesh, double nagata_eps,
                        const Parallel& parallel) {
  MeshReport r{{name, mesh_stats(mesh)}, {}, {}};
  for (Interpolant s : kSeed004Schemes) {
    const auto patches = build_patches(mesh, s, params_for(nagata_eps));
    r.curvature.push_back({name, s, nagata_eps, summarize(gaussian_curvature_samples(patches, kSeed004Segments, parallel))});
    r.edge_normals.push_back(
        {name, s, nagata_eps, summarize(adjacent_normal_cosines(mesh, patches, kSeed004Segments, parallel).cosines)});
  }
  return r;
}

std::vector<SchemeRow> seed004_table5(const Parallel& parallel) {
  std::vector<SchemeRow> rows;
  for (const NamedMesh& m : seed004_meshes())
    for (Interpolant s : kSeed004Schemes) {
      const auto patches = build_patches(m.mesh, s, params_for(m.nagata_eps));
      rows.push_back({m.name, s, m.nagata_eps, summarize(gaussian_curvature_samples(patches, kSeed004Segments, parallel))});
    }
  return rows;
}

std::vector<SchemeRow> seed004_table6(const Parallel& parallel) {
  std::vector<SchemeRow> rows;
  for (const NamedMesh& m : seed004_meshes())
    for (Interpolant s : kSeed004Schemes) {
      const auto patches = build_patches(m.mesh, s, params_for(m.nagata_eps));
      rows.push_back({m.name, s, m.nagata_eps,
                      summarize(adjacent_normal_cosines(m.mesh, patches, kSeed004Segments, parallel).cosines)});
    }
  return rows;
}

std::string format_table3(const std::vector<DistanceRow>& rows) {
  std::string out = printf_string("%-7s %-7s %-16s %-36s %s\n", "Name", "Step", "Scheme",
                                  "Mean distance ± std dev", "Min, max distance");
  std::string last;
  for (const DistanceRow& r : rows) {
    const std::string step = printf_string("%s = %d", r.surface == "Sphere" ? "i" : "j", r.step);
    const std::string key = r.surface + step;
    out += printf_string("%-7s %-7s %-16s %-36s %s\n", key == last ? "" : r.surface.c_str(),
                         key == last ? "" : step.c_str(), scheme_label(r.scheme, 0.0).c_str(),
                         mean_std(r.distance.mean, r.distance.seed004_table3_spread()).c_str(),
                         range(r.distance.min, r.distance.max).c_str());
    last = key;
  }
  return out;
}

std::string format_table4(const std::vector<MeshRow>& rows) {
  std::string out = printf_string("%-12s %-12s %-32s %-24s %-28s %s\n", "Name", "#V/#E/#T",
                                  "Mean angle normals ± std dev", "Min, max angle normals",
                                  "#E convex/concave/inflection", "(paper's counting)");
  for (const MeshRow& r : rows) {
    const MeshStats& s = r.stats;
    out += printf_string("%-12s %-12s %-32s %-24s %-28s %s\n", r.name.c_str(),
                         printf_string("%zu/%zu/%zu", s.vertices, s.edges, s.triangles).c_str(),
                         mean_std(s.normal_cosine.mean, s.normal_cosine.std_dev).c_str(),
                         range(s.normal_cosine.min, s.normal_cosine.max).c_str(),
                         printf_string("%g/%g/%g", s.shapes.convex, s.shapes.concave, s.shapes.inflection).c_str(),
                         printf_string("%g/%g/%g", s.seed004_shapes.convex, s.seed004_shapes.concave,
                                       s.seed004_shapes.inflection).c_str());
  }
  return out;
}

std::string format_table5(const std::vector<SchemeRow>& rows) {
  return format_scheme_rows(rows, "Mean Gaussian curv ± std dev");
}

std::string format_table6(const std::vector<SchemeRow>& rows) {
  return format_scheme_rows(rows, "Mean angle normals ± std dev");
}

nlohmann::json to_json(const Summary& s) {
  return {{"count", s.count}, {"mean", s.mean}, {"std_dev", s.std_dev}, {"min", s.min}, {"max", s.max}};
}

nlohmann::json to_json(const std::vector<DistanceRow>& rows) {
  nlohmann::json a = nlohmann::json::array();
  for (const DistanceRow& r : rows) {
    nlohmann::json d = to_json(r.distance);
    d["seed004_spread"] = r.distance.seed004_table3_spread();
    a.push_back({{"surface", r.surface}, {"step", r.step}, {"scheme", schemes::to_string(r.scheme)}, {"distance", d}});
  }
  return a;
}

nlohmann::json to_json(const std::vector<MeshRow>& rows) {
  auto shapes = [](const EdgeShapes& e) {
    return nlohmann::json{{"convex", e.convex}, {"concave", e.concave}, {"inflection", e.inflection}};
  };
  nlohmann::json a = nlohmann::json::array();
  for (const MeshRow& r : rows) {
    const MeshStats& s = r.stats;
    a.push_back({{"name", r.name},
                 {"vertices", s.vertices},
                 {"edges", s.edges},
                 {"triangles", s.triangles},
                 {"boundary_edges", s.boundary_edges},
                 {"nonmanifold_edges", s.nonmanifold_edges},
                 {"normal_cosine", to_json(s.normal_cosine)},
                 {"edge_shapes", shapes(s.shapes)},
                 {"edge_shapes_seed004_counting", shapes(s.seed004_shapes)}});
  }
  return a;
}

nlohmann::json to_json(const std::vector<SchemeRow>& rows) {
  nlohmann::json a = nlohmann::json::array();
  for (const SchemeRow& r : rows)
    a.push_back({{"mesh", r.mesh}, {"scheme", schemes::to_string(r.scheme)}, {"nagata_eps", r.nagata_eps},
                 {"value", to_json(r.value)}});
  return a;
}

}  // namespace tessref::stats
