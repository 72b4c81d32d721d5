// The backend registry (core/backend_registry.h): backends found by name, and the dressing
// stage handed out from the first backend that has one, whichever backend solves the steps.
#include "core/backend_registry.h"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace tightfit {
namespace {

// A stage that only says which it is: its dress() reports `frames` frames.
class CountingStage : public DressingStage {
 public:
  explicit CountingStage(int frames) : frames_(frames) {}
  DressingResult dress(const Problem&, const Garment&, const std::vector<Vec3>&,
                       const DressingSettings&) const override {
    DressingResult result;
    result.frames = frames_;
    return result;
  }
  SettledGarment settle(const Problem&, const std::vector<Vec3>& dressed_m, const LoadStep&,
                        const CoarseSettle&) const override {
    return {dressed_m, StepReport{}};
  }

 private:
  int frames_;
};

BackendEntry entry(const std::string& name, int stage_frames) {
  BackendEntry e;
  e.name = name;
  if (stage_frames > 0) e.dressing_stage = std::make_shared<CountingStage>(stage_frames);
  return e;
}

TEST(BackendRegistry, TheDressingStageIsTheFirstBackendsThatHasOne) {
  BackendRegistry registry;
  registry.add(entry("solver without stage", 0));
  registry.add(entry("first with stage", 7));
  registry.add(entry("second with stage", 9));
  const DressingResult dressed =
      registry.dressing_stage().dress(Problem{}, Garment{}, {}, DressingSettings{});
  EXPECT_EQ(dressed.frames, 7);
}

TEST(BackendRegistry, NoDressingStageIsAnErrorNamingTheBackends) {
  BackendRegistry registry;
  registry.add(entry("alpha", 0));
  registry.add(entry("beta", 0));
  try {
    registry.dressing_stage();
    FAIL() << "a registry without a dressing stage handed one out";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("alpha, beta"), std::string::npos) << e.what();
  }
  EXPECT_THROW(registry.find("gamma"), std::invalid_argument);
}

}  // namespace
}  // namespace tightfit
