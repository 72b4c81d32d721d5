// Seam labels in a pattern's outlines.png (io/outline_picture.h): a seam number is not drawn
// twice side by side (a dart's two legs), and different labels do not overlap.
#include "io/outline_picture.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace tightfit {
namespace {

TEST(OutlineLabels, ADartsTwoLegsShowTheirNumberOnce) {
  // The two legs of a narrow dart: labels 10 px apart with a 16 px font.
  const auto kept = labels_without_overlap({{"4", 100, 200}, {"4", 110, 200}}, 16);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0].x, 100);
}

TEST(OutlineLabels, TheSameNumberFarApartIsKeptOnBothPanels) {
  // A seam joins two panels: its number is drawn on each, 300 px apart.
  const auto kept = labels_without_overlap({{"4", 100, 200}, {"4", 400, 200}}, 16);
  EXPECT_EQ(kept.size(), 2u);
}

TEST(OutlineLabels, DifferentLabelsThatWouldOverlapAreSetALineApart) {
  const int font = 16;
  const auto kept = labels_without_overlap({{"12", 100, 200}, {"13", 105, 204}}, font);
  ASSERT_EQ(kept.size(), 2u);
  // Two 2-character labels are about 2 x 0.6 x 16 = 19 px wide: 5 px apart they overlap unless
  // a font height apart vertically.
  EXPECT_GE(std::abs(kept[1].y - kept[0].y), font);
  EXPECT_EQ(kept[0].y, 200);  // the first stays where it was put
}

TEST(OutlineLabels, LabelsApartStayWhereTheyArePut) {
  const auto kept = labels_without_overlap({{"1", 100, 200}, {"2", 160, 200}, {"3", 100, 260}}, 16);
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept[1].y, 200);
  EXPECT_EQ(kept[2].y, 260);
}

}  // namespace
}  // namespace tightfit
