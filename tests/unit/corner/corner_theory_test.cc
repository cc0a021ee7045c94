#include <corner/corner_theory.h>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
  using namespace FloorBlock;

  Corner::CornerMaterials
  rock(const double friction)
  {
    Corner::CornerMaterials materials;
    materials.rock                 = {6.7e9, 0.2};
    materials.friction_coefficient = friction;
    return materials;
  }
} // namespace

// A smooth contact edge (two half-planes, similar materials) has the
// exponents 1/2, 1, 3/2, 2, ... (the crack's, Williams 1952, since the
// open part of the interface is traction-free); a bounded traction that
// vanishes at the edge keeps 3/2 (t ~ d^(1/2), Hertz's edge; Johnson,
// Contact Mechanics, 1985, eq. 4.45 near x = a) and then 2.
TEST(CornerTheory, ASmoothEdgeInAFilletFallsLikeTheSquareRoot)
{
  for (const auto state :
       {Contact::JointState::stick, Contact::JointState::slip})
    for (const double friction : {0., std::tan(M_PI / 6.)})
      {
        Corner::CornerProfile profile;
        profile.kind       = Corner::CornerContactKind::edge_in_fillet;
        profile.edge_state = state;
        const auto theory =
          Corner::corner_theory(profile, rock(friction), 0.01);
        ASSERT_TRUE(theory.covered);
        EXPECT_NEAR(theory.exponent, 1.5, 1e-6);
        EXPECT_NEAR(theory.next_exponent, 2., 1e-6);
        EXPECT_NEAR(theory.pair.first_angle, M_PI, 1e-15);
        EXPECT_EQ(theory.pair.state,
                  friction == 0. ? Analytic::InterfaceState::frictionless :
                  state == Contact::JointState::slip ?
                                   Analytic::InterfaceState::slipping :
                                   Analytic::InterfaceState::stuck);
      }
}

// Two flush square corners stuck together are a half-plane: no singular
// mode, the lowest exponent is 1 (bounded stress; src/analytic/README.md,
// section 8).
TEST(CornerTheory, FlushSquareCornersStuckHaveABoundedField)
{
  Corner::CornerProfile profile;
  profile.kind       = Corner::CornerContactKind::reaches_corner;
  profile.edge_state = Contact::JointState::stick;
  const auto theory  = Corner::corner_theory(profile, rock(0.577), 0.);
  ASSERT_TRUE(theory.covered);
  EXPECT_NEAR(theory.exponent, 1., 1e-6);
  EXPECT_NE(theory.configuration.find("bounded"), std::string::npos);
}

TEST(CornerTheory, AnOpenCornerIsNotCovered)
{
  Corner::CornerProfile profile;
  profile.kind      = Corner::CornerContactKind::open_at_corner;
  const auto theory = Corner::corner_theory(profile, rock(0.577), 0.);
  EXPECT_FALSE(theory.covered);
  EXPECT_FALSE(theory.why_not.empty());
}

TEST(CornerTheory, CompliantJointsAreNotCovered)
{
  Corner::CornerProfile profile;
  profile.kind               = Corner::CornerContactKind::edge_in_fillet;
  auto materials             = rock(0.577);
  materials.exact_contact    = false;
  materials.compliant_length = 1.79;
  const auto theory          = Corner::corner_theory(profile, materials, 0.01);
  EXPECT_FALSE(theory.covered);
  EXPECT_NE(theory.configuration.find("1.79"), std::string::npos);
}

TEST(CornerTheory, AFilletClosedToItsEndIsNotCovered)
{
  Corner::CornerProfile profile;
  profile.kind       = Corner::CornerContactKind::reaches_corner;
  profile.edge_state = Contact::JointState::stick;
  const auto theory  = Corner::corner_theory(profile, rock(0.577), 0.02);
  EXPECT_FALSE(theory.covered);
  EXPECT_NE(theory.configuration.find("whole corner fillet"),
            std::string::npos);
}
