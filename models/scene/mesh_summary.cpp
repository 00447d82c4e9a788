#include "models/scene/mesh_summary.hpp"

#include "models/output/mesh_statistics.hpp"

namespace pc {

Json mesh_summary(const Scene& scene) {
  Json m = Json::object();
  m.set("description", Json(scene.mesh_description));
  if (scene.mesh_generator.empty()) {
    m.set("source", Json("gmsh"));
    m.set("file", Json(scene.mesh_file));
    m.set("size_factor", Json(scene.mesh_size_factor));
  } else {
    m.set("source", Json("generated"));
    m.set("generator", Json(scene.mesh_generator));
    m.set("nx", Json(scene.nx));
    m.set("ny", Json(scene.ny));
    if (scene.nz > 0) m.set("nz", Json(scene.nz));
    std::vector<Json> h;
    for (double x : scene.mesh_spacing) h.push_back(Json(x));
    m.set("h", Json::array(h));
  }
  if (!scene.spec.mesh) return m;
  const MeshStatistics s = mesh_statistics(*scene.spec.mesh);
  m.set("dim", Json(s.dim));
  m.set("nodes", Json(s.nodes));
  m.set("cells", Json(s.cells));
  m.set("cell_type", Json(to_string(s.cell_shape)));
  m.set("h_min", Json(s.h_min));
  m.set("h_max", Json(s.h_max));
  return m;
}

}  // namespace pc
