// A picture of a measured body for `tightfit measure`: the body from the front and from its
// left side, shaded grey, with the girths' tape lines and the landmarks drawn on it (red dots,
// names beside the front view). Drawn by io/raster_canvas.h.
#pragma once

#include "body/body_measurements.h"

#include <string>

namespace tightfit {

// Throws std::runtime_error naming `path` when it cannot be written.
void write_body_picture(const std::string& path, const TriangleSurface& surface,
                        const BodyMeasurements& m, const std::string& title);

}  // namespace tightfit
