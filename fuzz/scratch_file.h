// The readers under test take a path, as the program does: each input is written to a file
// of the right extension in the system's temporary directory, one per fuzzing process.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace tightfit::fuzz {

inline std::string write_scratch_file(const std::uint8_t* data, std::size_t size,
                                      const std::string& extension) {
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("tightfit_fuzz_" + std::to_string(getpid()) + "." + extension))
                               .string();
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

}  // namespace tightfit::fuzz
