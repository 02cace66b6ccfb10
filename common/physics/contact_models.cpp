// Model names to model objects, pair by pair.
#include "physics/contact_models.h"

#include <string>

namespace pool::physics {
namespace {

std::string unknown(const char* pair, const std::string& name) {
  return std::string("models.") + pair + ": unknown model '" + name + "'";
}

}  // namespace

Result<ContactModelSet> makeContactModels(const table::ContactModels& names,
                                          const table::PhysicsParams& params) {
  using R = Result<ContactModelSet>;
  ContactModelSet set;
  if (names.ball_cloth != "leckie_greenspan2005")
    return R::fail(unknown("ball_cloth", names.ball_cloth));
  set.cloth = makeClothLeckieGreenspan(params);
  if (names.ball_ball != "alciatore") return R::fail(unknown("ball_ball", names.ball_ball));
  set.ball_ball = makeBallBallAlciatore(params);
  if (names.ball_slate != "rigid_coulomb") return R::fail(unknown("ball_slate", names.ball_slate));
  set.slate = makeSlateRigidCoulomb(params);
  if (names.cue_ball != "alciatore") return R::fail(unknown("cue_ball", names.cue_ball));
  if (names.ball_cushion == "han2005") {
    set.cushion = makeCushionHan2005(params);
  } else if (names.ball_cushion == "mathavan2010") {
    set.cushion = makeCushionMathavan2010(params);
  } else if (names.ball_cushion == "stronge_compliant") {
    set.cushion = makeCushionStrongeCompliant(params);
  } else {
    return R::fail(unknown("ball_cushion", names.ball_cushion));
  }
  return R::ok(std::move(set));
}

}  // namespace pool::physics
