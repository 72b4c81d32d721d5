// "Did you mean": the edit distance against distances counted by hand, and which known names
// a misspelt one is offered.
#include "core/closest_names.h"

#include <gtest/gtest.h>

namespace tightfit {
namespace {

TEST(EditDistance, CountsInsertionsDeletionsSubstitutionsAndSwaps) {
  // kitten -> sitten -> sittin -> sitting: two substitutions and an insertion.
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("abc", ""), 3u);
  // One swap of neighbours, not two substitutions.
  EXPECT_EQ(edit_distance("Lwa", "Law"), 1u);
  // Case is not a difference.
  EXPECT_EQ(edit_distance("MATERIAL", "Material"), 0u);
  // Symmetric.
  EXPECT_EQ(edit_distance("Stifness weft", "Stiffness weft"),
            edit_distance("Stiffness weft", "Stifness weft"));
  EXPECT_EQ(edit_distance("Stifness weft", "Stiffness weft"), 1u);
}

TEST(ClosestNames, OffersTheNearestFirst) {
  const std::vector<std::string> known{"Stiffness warp", "Thickness", "Stiffness weft",
                                       "Shear stiffness"};
  const std::vector<std::string> near = closest_names("Stifness weft", known);
  ASSERT_FALSE(near.empty());
  EXPECT_EQ(near.front(), "Stiffness weft");
  // "Stiffness warp" is 4 edits away (f inserted, three letters of "weft"): within a third of
  // 14 letters, so offered after the nearer one.
  ASSERT_EQ(near.size(), 2u);
  EXPECT_EQ(near[1], "Stiffness warp");
}

TEST(ClosestNames, OffersANameThatContainsTheOther) {
  EXPECT_EQ(closest_names("hooke", {"linear biot", "neo hookean", "tensile curves"}),
            std::vector<std::string>{"neo hookean"});
}

TEST(ClosestNames, OffersNothingFarOrForOneLetterNames) {
  EXPECT_TRUE(closest_names("fly", {"run", "compare", "convergence"}).empty());
  // '9' is one edit from every one-letter edge name: none is nearer than another.
  EXPECT_TRUE(closest_names("9", {"0", "1", "2"}).empty());
}

TEST(DidYouMean, NamesTheClosestOrListsTheKnown) {
  EXPECT_EQ(did_you_mean("rnu", {"run", "compare"}), "; did you mean 'run'?");
  EXPECT_EQ(did_you_mean("9", {"0", "1", "2"}), "; known: '0', '1', '2'");
  EXPECT_EQ(did_you_mean("9", {"0", "1", "2"}, 2), "");
}

}  // namespace
}  // namespace tightfit
