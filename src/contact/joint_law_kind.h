#pragma once

/**
 * The joint-law choice, with no other dependency, so that the parameters
 * library parses Joints/Law straight into it (CMake target
 * floorblock_contact_kinds).
 */
namespace FloorBlock::Contact
{
  /** Interface law of a joint. */
  enum class JointLawKind
  {
    compliant, ///< UDEC joint: kn, ks springs with Coulomb slip
    rigid      ///< exact non-penetration and Coulomb friction (ExactContact)
  };
} // namespace FloorBlock::Contact
