#pragma once
// A scene's eigenfrequencies and mode shapes (`piezocontact modes SCENE`): the modal analysis
// (models/modal_analysis.hpp) of the model of the scene's first foundation, with its electrical
// conditions: grounded regions and electrodes short-circuited, other faces charge-free, or with
// open_circuit the electrodes floating (one unknown potential each, no net charge). Writes
//   DIR/modes.csv        mode, frequency_hz
//   DIR/mode_<k>.vtu     the shape of mode k: v (M-normalised) and phi, and the collection DIR/modes.pvd
// Contact is not part of the modes (the free or clamped body's).
#include <string>

#include "models/modal_analysis.hpp"
#include "models/scene/scene.hpp"

namespace pc {

// Empty directory: nothing is written. Throws naming the cause (no mass: material.rho = 0).
ModalResult write_scene_modes(const Scene& scene, const std::string& directory, const ModalOptions& options,
                              bool open_circuit = false);

}  // namespace pc
