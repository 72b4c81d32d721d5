// ParaView collection files (.pvd): a time series of VTU files.
//
// The collection is rewritten in full after every addition, through a temporary file renamed
// over the old one, so the .pvd on disk is complete and valid at every moment: a run stopped
// after step 3 still opens in ParaView with steps 1 to 3.
#pragma once

#include <string>
#include <vector>

namespace tightfit {

class PvdWriter {
 public:
  // Writes an empty collection to `path` at once. Throws std::runtime_error naming the path
  // when it cannot be written.
  explicit PvdWriter(std::string path);

  // Adds one dataset: `file` relative to the .pvd's folder, `time` the value ParaView shows
  // (for a load study, the step's alpha or its index). `part` tells apart datasets shown
  // together at one time (ParaView's "part" attribute). Rewrites the file; throws
  // std::runtime_error naming the path when it cannot.
  void add(double time, const std::string& file, int part = 0);

  const std::string& path() const { return path_; }
  std::size_t size() const { return entries_.size(); }

 private:
  struct Entry {
    double time;
    std::string file;
    int part;
  };
  void rewrite() const;

  std::string path_;
  std::vector<Entry> entries_;
};

}  // namespace tightfit
