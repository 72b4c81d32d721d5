// A body's measurements as a table on screen (cm), a JSON file and a CSV file (m), for
// `tightfit measure` (docs/measuring-bodies.md).
#pragma once

#include "body/body_measurements.h"
#include "io/text_table.h"

#include <string>

namespace tightfit {

// Girths and lengths in cm, landmarks in m.
std::vector<TextTable> measurement_tables(const BodyMeasurements& m);

// Throw std::runtime_error naming the path when it cannot be written.
void write_measurements_json(const std::string& path, const BodyMeasurements& m,
                             const std::string& source);
// One row per value: kind (girth, length, landmark), name, value_m, x_m, y_m, z_m.
void write_measurements_csv(const std::string& path, const BodyMeasurements& m);

}  // namespace tightfit
