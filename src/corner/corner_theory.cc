#include <corner/corner_theory.h>

#include <fmt/format.h>

#include <cmath>

namespace FloorBlock::Corner
{
  namespace
  {
    constexpr double pi = 3.14159265358979323846;

    /** Modes whose exponent differs from the last kept one by this much are
     * new. */
    constexpr double distinct_exponents = 1e-6;

    /**
     * The interface state the eigenproblem needs from the state of the
     * closed node nearest the edge: stick is stuck, slip is slipping in
     * the direction of its shear (sign of t_t / t_n in the profile's
     * tangent, which points up the joint, away from a top corner), a
     * friction coefficient of zero is frictionless.
     */
    void
    set_interface(const CornerProfile   &profile,
                  const CornerMaterials &materials,
                  Analytic::WedgePair   &pair)
    {
      pair.friction_coefficient = materials.friction_coefficient;
      if (materials.friction_coefficient == 0.)
        pair.state = Analytic::InterfaceState::frictionless;
      else if (profile.edge_state == Contact::JointState::slip)
        {
          pair.state     = Analytic::InterfaceState::slipping;
          pair.slip_sign = profile.edge_traction_ratio >= 0. ? 1 : -1;
        }
      else
        pair.state = Analytic::InterfaceState::stuck;
    }
  } // namespace

  const char *
  to_string(const Analytic::InterfaceState state)
  {
    switch (state)
      {
        case Analytic::InterfaceState::stuck:
          return "stuck";
        case Analytic::InterfaceState::frictionless:
          return "frictionless";
        case Analytic::InterfaceState::slipping:
          return "slipping";
      }
    return "?";
  }

  CornerTheory
  corner_theory(const CornerProfile   &profile,
                const CornerMaterials &materials,
                const double           rounding_radius)
  {
    CornerTheory theory;
    theory.pair.first_material  = materials.rock;
    theory.pair.second_material = materials.rock;
    set_interface(profile, materials, theory.pair);
    Analytic::RootSearch search;
    search.largest_real_part = 3.;
    if (!materials.exact_contact &&
        profile.kind != CornerContactKind::open_at_corner)
      {
        theory.configuration =
          "compliant joints: the springs kn spread the corner's contact "
          "over about E/kn = " +
          fmt::format("{:.3g}", materials.compliant_length) + " m";
        theory.why_not =
          "the wedge eigenproblem assumes exact contact (Joints/Law = "
          "rigid); a spring layer has no corner singularity, its traction "
          "is kn times the overlap";
        return theory;
      }

    switch (profile.kind)
      {
        case CornerContactKind::open_at_corner:
          theory.configuration =
            "the joint is open at the corner: the contact zone ends below it "
            "on the straight joint";
          theory.why_not = "no traction at the corner to characterise";
          return theory;
          case CornerContactKind::edge_in_fillet: {
            theory.configuration =
              "the contact ends inside the corner fillets: an incomplete "
              "contact whose edge is smooth (two half-planes locally)";
            theory.pair.first_angle  = pi;
            theory.pair.second_angle = pi;
            theory.modes = Analytic::corner_modes(theory.pair, search);
            // Bounded traction falling to zero at the edge: Re lambda > 1.
            std::vector<double> kept;
            for (const auto &mode : theory.modes)
              if (mode.exponent.real() > 1. + distinct_exponents &&
                  (kept.empty() ||
                   mode.exponent.real() > kept.back() + distinct_exponents))
                kept.push_back(mode.exponent.real());
            if (kept.size() < 2)
              {
                theory.why_not = "the eigen-solver found fewer than two "
                                 "modes above lambda = 1";
                return theory;
              }
            theory.exponent       = kept[0];
            theory.next_exponent  = kept[1];
            theory.third_exponent = kept.size() > 2 ? kept[2] : 0.;
            theory.covered        = true;
            return theory;
          }
          case CornerContactKind::reaches_corner: {
            if (rounding_radius > 0.)
              {
                theory.configuration =
                  "the contact covers the whole corner fillet up to the "
                  "block top";
                theory.why_not =
                  "a fillet closed to its end is not a corner the wedge "
                  "eigenproblem describes (nor expected under a small "
                  "rotation: check the mesh)";
                return theory;
              }
            theory.configuration =
              "the contact reaches the sharp corner: two flush block "
              "corners (pi/2 on pi/2) in complete contact";
            theory.pair.first_angle  = pi / 2.;
            theory.pair.second_angle = pi / 2.;
            theory.modes = Analytic::corner_modes(theory.pair, search);
            if (theory.modes.size() < 2)
              {
                theory.why_not = "the eigen-solver found fewer than two modes";
                return theory;
              }
            theory.exponent      = theory.modes[0].exponent.real();
            theory.next_exponent = theory.modes[1].exponent.real();
            theory.third_exponent =
              theory.modes.size() > 2 ? theory.modes[2].exponent.real() : 0.;
            theory.covered = true;
            if (theory.exponent >= 1.)
              theory.configuration += "; no singular mode (lowest lambda " +
                                      std::to_string(theory.exponent) +
                                      "): the corner traction is bounded";
            return theory;
          }
      }
    return theory;
  }
} // namespace FloorBlock::Corner
