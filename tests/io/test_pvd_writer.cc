// ParaView collections parsed back: as XML by VTK's parser, and as plain text.
#include "io/pvd_writer.h"
#include "scratch_dir.h"

#include <gtest/gtest.h>
#include <vtkNew.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <regex>

namespace tightfit {
namespace {

using PvdFile = ScratchDir;

struct DataSetEntry {
  std::string timestep, part, file;
};

// The DataSet entries of a .pvd, read with VTK's XML parser (so the file must be well-formed).
std::vector<DataSetEntry> parse_pvd(const std::string& path) {
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(path.c_str());
  EXPECT_EQ(parser->Parse(), 1) << path << " is not well-formed XML";
  std::vector<DataSetEntry> entries;
  vtkXMLDataElement* root = parser->GetRootElement();
  if (!root) return entries;
  EXPECT_STREQ(root->GetName(), "VTKFile");
  EXPECT_STREQ(root->GetAttribute("type"), "Collection");
  vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
  EXPECT_NE(collection, nullptr);
  if (!collection) return entries;
  for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i) {
    vtkXMLDataElement* e = collection->GetNestedElement(i);
    EXPECT_STREQ(e->GetName(), "DataSet");
    entries.push_back(
        {e->GetAttribute("timestep"), e->GetAttribute("part"), e->GetAttribute("file")});
  }
  return entries;
}

TEST_F(PvdFile, IsValidAndCompleteAfterEveryAddition) {
  const std::string file = path("garment.pvd");
  PvdWriter pvd(file);
  EXPECT_TRUE(parse_pvd(file).empty());

  const std::vector<double> alpha = {1.0, 1.08, 1.16};
  for (std::size_t step = 0; step < alpha.size(); ++step) {
    const std::string name = "garment_000" + std::to_string(step) + ".vtu";
    pvd.add(alpha[step], name);
    // Read while the writer lives: the file already lists every step added so far.
    const auto entries = parse_pvd(file);
    ASSERT_EQ(entries.size(), step + 1);
    for (std::size_t i = 0; i <= step; ++i) {
      EXPECT_EQ(entries[i].file, "garment_000" + std::to_string(i) + ".vtu");
      EXPECT_EQ(std::stod(entries[i].timestep), alpha[i]);
      EXPECT_EQ(entries[i].part, "0");
    }
  }
  EXPECT_EQ(pvd.size(), 3u);
  EXPECT_FALSE(std::filesystem::exists(file + ".tmp"));
}

TEST_F(PvdFile, PlainTextListsTheFilesInOrder) {
  const std::string file = path("body.pvd");
  PvdWriter pvd(file);
  pvd.add(0.0, "body_0000.vtu");
  pvd.add(2.5, "body_0001.vtu");
  const std::string text = read_text(file);
  const std::regex dataset(
      "<DataSet timestep=\"([^\"]*)\" group=\"\" part=\"0\" file=\"([^\"]*)\" ?/>");
  std::vector<std::string> files, times;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), dataset);
       it != std::sregex_iterator(); ++it) {
    times.push_back((*it)[1]);
    files.push_back((*it)[2]);
  }
  EXPECT_EQ(files, (std::vector<std::string>{"body_0000.vtu", "body_0001.vtu"}));
  EXPECT_EQ(times, (std::vector<std::string>{"0", "2.5"}));
  EXPECT_EQ(text.rfind("</VTKFile>\n"), text.size() - 11);
}

TEST_F(PvdFile, PartsAndAwkwardNamesSurviveTheRoundTrip) {
  const std::string file = path("all.pvd");
  PvdWriter pvd(file);
  pvd.add(1.0, "garment & body <1>.vtu", 0);
  pvd.add(1.0, "body \"1\".vtu", 1);
  const auto entries = parse_pvd(file);
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_EQ(entries[0].file, "garment & body <1>.vtu");
  EXPECT_EQ(entries[1].file, "body \"1\".vtu");
  EXPECT_EQ(entries[0].part, "0");
  EXPECT_EQ(entries[1].part, "1");
}

TEST(PvdWriter, UnwritablePathThrowsNamingIt) {
  const std::string bad = "/nonexistent_tightfit_dir/garment.pvd";
  try {
    PvdWriter pvd(bad);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tightfit
