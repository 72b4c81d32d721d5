// The ParaView view of a run (docs/reading-output.md, "The view script"): a Python script for
// ParaView 5.11 (pvpython, or the GUI's Python shell) written beside the run's .pvd files. It
// opens the garment and body series, colours both by pressure on one colour map with a colour
// bar titled with the unit, shows the load steps as time (the .pvd times are the steps' alpha),
// draws the garment's edge, frames the scene from the front and, when the run writes an
// angular profile, adds it as a line chart.
//
// The script holds what the run knows (file and field names, the unit, the view) as a settings
// block at its top; the rest is fixed code. It finds its files in its own folder (the folder it
// was written to if Python does not tell it where it is), so an output folder can be moved.
#pragma once

#include "core/types.h"

#include <string>

namespace tightfit {

struct ViewScriptSettings {
  std::string title;  // shown above the view: the case's garment and body
  std::string garment_series = "garment.pvd";
  std::string body_series = "body.pvd";
  // body.pvd carries pressure_Pa and pressure_mmHg (Output/Body pressure); otherwise the body
  // is drawn in plain grey.
  bool body_has_pressure = true;
  // Pressure in mmHg on the colour bar (medical cases); Pa otherwise. The garment's mmHg are
  // computed in ParaView from its pressure_Pa (a Calculator), the body's read from the file.
  bool in_mmHg = false;
  // The angular profile's CSV (theta_deg, pressure_Pa, p_theory_Pa columns), empty if the run
  // writes none.
  std::string angular_profile_csv;
  Vec3 view_direction = Vec3::UnitY();  // the camera looks along it ("front")
  Vec3 view_up = Vec3::UnitZ();
};

// The script's text.
std::string paraview_view_script(const ViewScriptSettings& settings,
                                 const std::string& written_to_directory);

// Writes the script to `path` (its folder must exist). Throws std::runtime_error naming the path
// when it cannot be written, std::invalid_argument when the view direction is zero or along up.
void write_paraview_view_script(const std::string& path, const ViewScriptSettings& settings);

}  // namespace tightfit
