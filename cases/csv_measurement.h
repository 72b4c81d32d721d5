// The base of a measurement that writes a CSV file of its own, rows added after every load
// step (sensors.csv, regions.csv, ...): a subclass names the file and its columns and gives
// each step's rows; opening, the header, flushing and MPI (the first rank writes) are done
// here. docs/scenarios.md shows a whole one.
#pragma once

#include "cases/measurement.h"
#include "io/csv_table.h"

#include <memory>
#include <string>
#include <vector>

namespace tightfit {

class CsvMeasurement : public Measurement {
 public:
  CsvMeasurement(std::string file_name, std::vector<std::string> columns);
  void after_step(const Scenario& scenario, const StepMeasurement& step,
                  const RunFiles& files) override;
  std::vector<std::string> file_names() const override { return {file_name_}; }

 protected:
  // The rows of one load step (one per sensor, region, ...), each with one cell per column.
  virtual std::vector<std::vector<CsvCell>> rows(const Scenario& scenario,
                                                 const StepMeasurement& step) = 0;

 private:
  std::string file_name_;
  std::vector<std::string> columns_;
  std::unique_ptr<CsvTable> table_;
};

}  // namespace tightfit
