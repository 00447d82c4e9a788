#include "models/scene/scene_modes.hpp"

#include <filesystem>
#include <fstream>

#include "assembly/error.hpp"
#include "assembly/processes.hpp"
#include "assembly/vtu_writer.hpp"
#include "models/output/csv_log.hpp"
#include "models/piezo/electrodes.hpp"
#include "models/scene/scene_runner.hpp"

namespace pc {

ModalResult write_scene_modes(const Scene& scene, const std::string& directory, const ModalOptions& options,
                              bool open_circuit) {
  require(scene.spec.rho > 0,
          "modes: the scene's body has no mass (material.rho = 0): a quasi-static model has no "
          "vibration modes");
  Scene circuit = scene;
  if (open_circuit) {
    require(!scene.spec.electrodes.empty(), "modes: --open-circuit, but the scene has no electrodes to open");
    for (Electrode& e : circuit.spec.electrodes) e = floating_electrode(e.name, e.region);
  }
  FoundationRun run(circuit, circuit.foundations.front());
  Model& model = run.model();
  const ModalResult modes = modal_analysis(model, options);
  if (directory.empty() || !processes::is_writer()) return modes;
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  require(!error && std::filesystem::is_directory(directory), "modes: cannot create the output directory '", directory,
          "': ", error ? error.message() : "a file of that name is in the way");
  std::vector<std::vector<double>> rows;
  for (size_t k = 0; k < modes.frequencies_hz.size(); ++k) rows.push_back({double(k + 1), modes.frequencies_hz[k]});
  write_csv(directory + "/modes.csv", {"mode", "frequency_hz"}, rows);
  std::ofstream pvd(directory + "/modes.pvd");
  pvd << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
  for (size_t k = 0; k < modes.frequencies_hz.size(); ++k) {
    VtuWriter writer(model.mesh());
    writer.add_point_field("v", model.space("v"), modes.velocity_shapes.col(Eigen::Index(k)));
    if (modes.potential_shapes.size() > 0)
      writer.add_point_field("phi", model.space("phi"), modes.potential_shapes.col(Eigen::Index(k)));
    const std::string file = "mode_" + std::to_string(k + 1) + ".vtu";
    writer.write(directory + "/" + file);
    // ParaView steps through the modes as "times": the frequencies.
    pvd << "    <DataSet timestep=\"" << modes.frequencies_hz[k] << "\" file=\"" << file << "\"/>\n";
  }
  pvd << "  </Collection>\n</VTKFile>\n";
  require(pvd.good(), "modes: cannot write '", directory, "/modes.pvd'");
  return modes;
}

}  // namespace pc
