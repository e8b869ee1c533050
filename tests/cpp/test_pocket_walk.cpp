// The periodic walk of a roller through its cage pocket (CageModel::Walls), against walks worked
// out by hand: the share of each azimuth step a roller spends at a pocket wall.
#include <gtest/gtest.h>

#include <algorithm>

#include "kegel/core/quasi_static.hpp"

TEST(PocketWalk, InsideTheClearanceNoWallIsMet) {
  // leads +-1 um alternating: the roller swings by 1 um in a +-5 um pocket
  const double lead[4] = {1e-6, -1e-6, 1e-6, -1e-6};
  const int state[4] = {0, 0, 0, 0};
  double share[4];
  kegel::periodic_pocket_walk(lead, state, 4, 5e-6, share);
  for (double s : share) EXPECT_EQ(s, 0.0);
}

TEST(PocketWalk, AlwaysLeadingIsAlwaysAtTheFrontWall) {
  // +3 per step in a +-2 pocket: from any start the roller reaches the front wall in the first
  // step and stays there, so the periodic walk starts at +2 and spends both steps at the wall
  const double lead[2] = {3.0, 3.0};
  const int state[2] = {0, 0};
  double share[2];
  const double x0 = kegel::periodic_pocket_walk(lead, state, 2, 2.0, share);
  EXPECT_NEAR(x0, 2.0, 1e-12);
  EXPECT_NEAR(share[0], 1.0, 1e-12);
  EXPECT_NEAR(share[1], 1.0, 1e-12);
}

TEST(PocketWalk, ANetDriftIsTakenByTheWallOnce) {
  // +3 then -1 in a +-1 pocket (net +2 per revolution): periodic from x0 = 0, the roller meets
  // the front wall after 1 of the 3 units of step 0 (share 2/3), then falls back to 0 in step 1
  const double lead[2] = {3.0, -1.0};
  const int state[2] = {0, 0};
  double share[2];
  const double x0 = kegel::periodic_pocket_walk(lead, state, 2, 1.0, share);
  EXPECT_NEAR(x0, 0.0, 1e-12);
  EXPECT_NEAR(share[0], 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(share[1], 0.0, 1e-12);
}

TEST(PocketWalk, ALockedRollerSetsTheWalkOffFromItsWall) {
  // step 1 locked at the front wall (+1); then -0.5 twice in a +-1 pocket: 1 -> 0.5 -> 0, back
  // at step 1; unloaded steps (state 2) keep the lead
  const double lead[4] = {-0.5, 0.0, 0.0, -0.5};
  const int state[4] = {0, 1, 2, 0};
  double share[4];
  const double x0 = kegel::periodic_pocket_walk(lead, state, 4, 1.0, share);
  EXPECT_NEAR(x0, 0.5, 1e-12);
  EXPECT_NEAR(share[0], 0.0, 1e-12);
  EXPECT_NEAR(share[1], 1.0, 1e-12);
  EXPECT_NEAR(share[2], 0.0, 1e-12);
  EXPECT_NEAR(share[3], 0.0, 1e-12);
}

TEST(PocketWalk, SharesGrowFromZeroAsTheSwingExceedsTheClearance) {
  // a swing of 2 a (leads +a, +a, -a, -a) in a +-1 pocket: no wall while a <= 1; beyond, both
  // walls are met with shares that grow continuously from 0
  const int state[4] = {0, 0, 0, 0};
  double prev = 0.0;
  for (double a : {0.9, 1.0, 1.01, 1.1, 1.5, 3.0}) {
    const double lead[4] = {a, a, -a, -a};
    double share[4];
    kegel::periodic_pocket_walk(lead, state, 4, 1.0, share);
    double total = 0.0;
    for (double s : share) total += s;
    if (a <= 1.0) EXPECT_NEAR(total, 0.0, 1e-9) << a;
    else EXPECT_GT(total, prev) << a;
    // by hand: the periodic walk leaves the back wall (-1) at step 0 and travels 2 a forward
    // over steps 0-1, of which 2 a - 2 lie beyond the front wall (+1); each step lasts a units
    // of travel, so the forward half spends (2 a - 2) / a steps at the wall, and the backward
    // half the same: total 2 (2 a - 2) / a (1 < a; e.g. a = 3: 1/3 + 1 + 1/3 + 1 = 8/3)
    EXPECT_NEAR(total, 2.0 * std::max(0.0, 2.0 * a - 2.0) / a, 1e-9) << a;
    prev = total;
  }
}
