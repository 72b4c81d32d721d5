// Body/Kind = morph: the mesh of Body/Mesh changing between load steps
// (bodies/morphing_mesh_body.h). With a target mesh of the same connectivity (MakeHuman's
// default female and male share theirs) alpha is the blend t: the garment settles on the base
// (t = 0) and each load step moves the body towards the target, which it reaches at alpha = 1.
// Without one, alpha is a scale about a point or an axis, from 1 (the body as read).
#include "bodies/morphing_mesh_body.h"
#include "cases/parts/mesh_body_settings.h"
#include "cases/parts/part_entries.h"

#include <cstdio>
#include <stdexcept>

namespace tightfit {

namespace {

class MorphScenarioBody final : public ScenarioBody {
 public:
  MorphScenarioBody(std::unique_ptr<MorphingMeshBody> body, std::string description, bool blends)
      : body_(std::move(body)), description_(std::move(description)), blends_(blends) {}
  const RigidBody& body() const override { return *body_; }
  double initial_alpha() const override { return blends_ ? 0.0 : 1.0; }
  void morph(int step, double alpha) override {
    if (step == 0) alpha = initial_alpha();
    if (blends_)
      body_->set_morph(alpha, 1.0);
    else
      body_->set_morph(0.0, alpha);
  }
  void check_final_alpha(double final_alpha) const override {
    if (blends_ && !(final_alpha > 0.0 && final_alpha <= 1.0))
      throw std::invalid_argument(
          "Protocol/Final alpha must lie in (0, 1] for a morph towards a target mesh (alpha is "
          "the blend), not " +
          std::to_string(final_alpha));
    if (!blends_ && !(final_alpha > 0.0))
      throw std::invalid_argument("Protocol/Final alpha (the body's scale) must be positive");
  }
  std::string describe() const override { return description_; }

 private:
  std::unique_ptr<MorphingMeshBody> body_;
  std::string description_;
  bool blends_;
};

}  // namespace

PartEntry<BodyMaker> morph_body_entry() {
  PartEntry<BodyMaker> e;
  e.name = "morph";
  e.subsection = "Morph";
  e.description =
      "the mesh of Body/Mesh blended towards a target mesh of the same connectivity (alpha = the "
      "blend, 0 to 1) or, without one, scaled about a point or an axis (alpha = the scale).";
  e.declare_parameters = [](ParameterTree& prm) {
    prm.declare_file_name("Target mesh", "",
                          "Surface mesh the body becomes at alpha = 1, with the same vertices "
                          "and faces as Body/Mesh/File and the same import options; empty to "
                          "scale instead.");
    prm.declare_selection("Scale about", "axis", "point|axis",
                          "Without a target mesh: scale about a point (every distance) or about "
                          "an axis (distances from it; lengths along it stay).");
    prm.declare_vector("Scale centre", "0,0,0",
                       "The fixed point, or a point on the fixed axis (m).");
    prm.declare_vector("Scale axis", "0,0,1", "The fixed axis when scaling about an axis (-).");
  };
  e.parse = [](ParameterTree& prm) -> BodyMaker {
    const std::string target = prm.get_file_name("Target mesh");
    BodyScaling scaling;
    scaling.about =
        prm.get("Scale about") == "point" ? BodyScaling::About::point : BodyScaling::About::axis;
    scaling.centre_m = prm.get_vector("Scale centre");
    scaling.axis = prm.get_vector("Scale axis");
    if (scaling.about == BodyScaling::About::axis && !(scaling.axis.norm() > 0))
      throw std::invalid_argument("Scale axis must not be zero");
    // The base shape is Body/Mesh's.
    prm.leave_subsection();
    MeshBodySettings base;
    try {
      Subsection mesh(prm, "Mesh");
      base = parse_mesh_body_settings(prm);
    } catch (const std::invalid_argument& error) {
      prm.enter_subsection("Morph");
      throw std::invalid_argument(std::string("needs Body/Mesh: ") + error.what());
    }
    prm.enter_subsection("Morph");
    return [=](const Garment&) -> std::unique_ptr<ScenarioBody> {
      auto body = load_morphing_mesh_body(base.file, target, base.options, scaling);
      const std::string what = target.empty()
                                   ? "mesh body '" + base.file + "' scaled by alpha"
                                   : "mesh body '" + base.file + "' morphing into '" + target + "'";
      return std::make_unique<MorphScenarioBody>(std::move(body), what, !target.empty());
    };
  };
  return e;
}

}  // namespace tightfit
