// The ring the window draws round what a click would call: a closed circle at the given height.
#include <gtest/gtest.h>

#include <cmath>

#include "client/app/overlay.h"

namespace pool::app::test {
namespace {

TEST(OverlayRing, IsAClosedCircleOfItsRadiusAtItsHeight) {
  const Eigen::Vector2d centre(1.22, 0.585);
  const Eigen::Vector3d colour(0.2, 1.0, 0.3);
  const auto ring = ringOverlay(centre, 0.08, 0.01, colour);
  ASSERT_GE(ring.size(), 16u);
  for (std::size_t i = 0; i < ring.size(); ++i) {
    for (const Eigen::Vector3d& p : {ring[i].a, ring[i].b}) {
      EXPECT_NEAR((p.head<2>() - centre).norm(), 0.08, 1e-12);
      EXPECT_DOUBLE_EQ(p.z(), 0.01);
    }
    EXPECT_EQ(ring[i].colour, colour);
    // Each segment starts where the last one ended; the last ends where the first began.
    EXPECT_LT((ring[i].a - ring[(i + ring.size() - 1) % ring.size()].b).norm(), 1e-12);
  }
}

}  // namespace
}  // namespace pool::app::test
