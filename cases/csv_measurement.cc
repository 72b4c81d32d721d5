#include "cases/csv_measurement.h"

namespace tightfit {

CsvMeasurement::CsvMeasurement(std::string file_name, std::vector<std::string> columns)
    : file_name_(std::move(file_name)), columns_(std::move(columns)) {}

void CsvMeasurement::after_step(const Scenario& scenario, const StepMeasurement& step,
                                const RunFiles& files) {
  // Every rank measures (the rows may need every rank's data); the first one writes.
  const std::vector<std::vector<CsvCell>> step_rows = rows(scenario, step);
  if (!files.write_tables) return;
  if (!table_) table_ = std::make_unique<CsvTable>(files.path(file_name_), columns_);
  for (const auto& row : step_rows) table_->write_row(row);
}

}  // namespace tightfit
