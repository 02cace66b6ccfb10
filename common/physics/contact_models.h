// The contact models of a table, made from the names its spec gives for each pair of bodies.
#pragma once

#include <memory>

#include "core/result.h"
#include "physics/ball_ball/ball_ball_model.h"
#include "physics/ball_cloth/cloth_model.h"
#include "physics/ball_cushion/cushion_model.h"
#include "physics/ball_slate/slate_model.h"
#include "table/contact_models.h"
#include "table/physics_params.h"

namespace pool::physics {

/// One model per contact pair (the cue strike has a single model, cue_strike.h).
struct ContactModelSet {
  std::unique_ptr<ClothModel> cloth;
  std::unique_ptr<BallBallModel> ball_ball;
  std::unique_ptr<CushionModel> cushion;
  std::unique_ptr<SlateModel> slate;
};

/// Makes the models `names` chooses, with the coefficients `params`. Fails on a name no model
/// has, with "models.<pair>: unknown model '<name>' (known: ...)".
Result<ContactModelSet> makeContactModels(const table::ContactModels& names,
                                          const table::PhysicsParams& params);

}  // namespace pool::physics
