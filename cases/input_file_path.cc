#include "cases/input_file_path.h"

#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace tightfit {

std::string resolve_input_file(const std::string& name, const std::string& case_directory) {
  namespace fs = std::filesystem;
  if (name.empty()) return name;
  auto readable = [](const fs::path& p) {
    std::error_code ignored;
    return fs::exists(p, ignored) && !fs::is_directory(p, ignored);
  };
  const fs::path written(name);
  if (readable(written)) return name;
  std::vector<fs::path> tried{written.is_absolute() ? written : fs::absolute(written)};
  if (written.is_relative() && !case_directory.empty()) {
    const fs::path beside = fs::path(case_directory) / written;
    if (readable(beside)) return beside.lexically_normal().string();
    tried.push_back(fs::absolute(beside).lexically_normal());
  }
  std::string message = "'" + name + "': cannot open the file; tried " + tried[0].string();
  if (written.is_relative()) message += " (relative to the working directory)";
  if (tried.size() > 1) message += " and " + tried[1].string() + " (relative to the case file)";
  throw std::invalid_argument(message);
}

}  // namespace tightfit
