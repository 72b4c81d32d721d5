#include "io/vtk_reader_run.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkSmartPointer.h>

#include <sstream>

namespace tightfit {
namespace {

// Keeps the words of each report: VTK prefixes them with "ERROR: In file, line n" and
// "vtkClass (address): ".
void collect_message(vtkObject*, unsigned long, void* client_data, void* call_data) {
  auto* messages = static_cast<std::string*>(client_data);
  if (!call_data) return;
  std::istringstream lines(static_cast<const char*>(call_data));
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind("ERROR: In", 0) == 0 || line.rfind("Warning: In", 0) == 0) continue;
    const auto address_end = line.find("): ");
    if (line.rfind("vtk", 0) == 0 && address_end != std::string::npos)
      line = line.substr(address_end + 3);
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    *messages += (messages->empty() ? "" : "; ") + line;
    break;  // the first line says what; the rest is VTK's pipeline detail
  }
}

vtkSmartPointer<vtkCallbackCommand> collector(std::string& messages) {
  auto observer = vtkSmartPointer<vtkCallbackCommand>::New();
  observer->SetCallback(collect_message);
  observer->SetClientData(&messages);
  return observer;
}

}  // namespace

std::string update_reader_quietly(vtkAlgorithm& reader) {
  // The reader's own reports say what is wrong; the pipeline's only that the reader failed.
  std::string messages, pipeline_messages;
  auto observer = collector(messages);
  auto pipeline_observer = collector(pipeline_messages);
  const unsigned long error_tag = reader.AddObserver(vtkCommand::ErrorEvent, observer);
  const unsigned long warning_tag = reader.AddObserver(vtkCommand::WarningEvent, observer);
  const unsigned long pipeline_tag =
      reader.GetExecutive()->AddObserver(vtkCommand::ErrorEvent, pipeline_observer);
  reader.Update();
  reader.RemoveObserver(error_tag);
  reader.RemoveObserver(warning_tag);
  reader.GetExecutive()->RemoveObserver(pipeline_tag);
  if (messages.empty()) messages = pipeline_messages;
  if (messages.empty() && reader.GetErrorCode() != 0)
    messages = "error code " + std::to_string(reader.GetErrorCode());
  return messages;
}

}  // namespace tightfit
