#include "rotated_chain_system.h"

#include <cmath>

#include "dense_solver.h"

namespace FloorBlock::AnalyticTest
{
  namespace
  {
    struct Vector2
    {
      double x;
      double y;
    };

    Vector2
    operator+(const Vector2 a, const Vector2 b)
    {
      return {a.x + b.x, a.y + b.y};
    }

    Vector2
    operator*(const double factor, const Vector2 v)
    {
      return {factor * v.x, factor * v.y};
    }

    /** z component of r x F, the moment of F applied at r. */
    double
    moment(const Vector2 lever, const Vector2 force)
    {
      return lever.x * force.y - lever.y * force.x;
    }

    /** Unit vectors along (away from the face, up-dip) and normal to the
     * bedding of one block, global axes x away from the face, y up. */
    struct BlockFrame
    {
      Vector2 along;
      Vector2 normal;
    };

    BlockFrame
    frame(const double inclination)
    {
      return {{std::cos(inclination), std::sin(inclination)},
              {-std::sin(inclination), std::cos(inclination)}};
    }

    /**
     * Corner positions relative to the face-side top corner T of a block:
     * the other top corner, the uphill and face-side base corners, the
     * centroid and the support-load point.
     */
    struct BlockPoints
    {
      Vector2 away_top;
      Vector2 uphill_base;
      Vector2 face_base;
      Vector2 centroid;
      Vector2 support_point;
    };

    BlockPoints
    points(const Analytic::BlockChain &chain, const BlockFrame &axes)
    {
      const double width = chain.block_width, height = chain.block_height;
      BlockPoints  corners;
      corners.away_top    = width * axes.along;
      corners.uphill_base = width * axes.along + (-height) * axes.normal;
      corners.face_base   = (-height) * axes.normal;
      corners.centroid =
        (width / 2.) * axes.along + (-height / 2.) * axes.normal;
      corners.support_point =
        ((1. - chain.support_load_position) * width) * axes.along;
      return corners;
    }

    /**
     * Add one force, linear in one unknown, to the x, y and moment rows of
     * a block. The force is coefficient * unknown, applied at lever
     * (relative to the moment point).
     */
    void
    add_force(DenseSystem       &system,
              const unsigned int first_row,
              const unsigned int n_rows,
              const unsigned int unknown,
              const Vector2      coefficient,
              const Vector2      lever)
    {
      system.add(first_row, unknown, coefficient.x);
      system.add(first_row + 1, unknown, coefficient.y);
      if (n_rows == 3)
        system.add(first_row + 2, unknown, moment(lever, coefficient));
    }

    /** Gravity and support load go to the right-hand side. */
    void
    add_loads(DenseSystem                &system,
              const unsigned int          first_row,
              const unsigned int          n_rows,
              const Analytic::BlockChain &chain,
              const unsigned int          block,
              const BlockPoints          &corners,
              const Vector2               moment_point)
    {
      const Vector2 weight  = {0., -chain.weight[block]};
      const Vector2 support = {0., -chain.support_load[block]};
      system.add_rhs(first_row, -(weight.x + support.x));
      system.add_rhs(first_row + 1, -(weight.y + support.y));
      if (n_rows == 3)
        system.add_rhs(
          first_row + 2,
          -(moment(corners.centroid + (-1.) * moment_point, weight) +
            moment(corners.support_point + (-1.) * moment_point, support)));
    }
  } // namespace

  RotatedChainSolution
  solve_rotated_chain_without_joint_slip(const Analytic::BlockChain &chain)
  {
    const unsigned int n_blocks    = chain.n_blocks();
    const double       tan_bedding = std::tan(chain.bedding_friction);
    // Unknowns: Q_i at i, V_i at n + i, N_i at 2n + i.
    DenseSystem system(3 * n_blocks);
    for (unsigned int block = 0; block < n_blocks; ++block)
      {
        const unsigned int row         = 3 * block;
        const BlockFrame   axes        = frame(chain.inclination[block]);
        const BlockPoints  corners     = points(chain, axes);
        const Vector2      pivot       = corners.uphill_base;
        const Vector2      at_face_top = (-1.) * pivot;
        // Joint i on block i at T: +Q along, -V normal (own frame).
        add_force(system, row, 3, block, axes.along, at_face_top);
        add_force(
          system, row, 3, n_blocks + block, (-1.) * axes.normal, at_face_top);
        if (block > 0)
          {
            // Joint i-1, in the frame of block i-1, reversed, at the
            // away-side top corner of block i.
            const BlockFrame away_axes   = frame(chain.inclination[block - 1]);
            const Vector2    at_away_top = corners.away_top + (-1.) * pivot;
            add_force(
              system, row, 3, block - 1, (-1.) * away_axes.along, at_away_top);
            add_force(system,
                      row,
                      3,
                      n_blocks + block - 1,
                      away_axes.normal,
                      at_away_top);
          }
        // Base: normal plus friction towards the face, through the pivot.
        add_force(system,
                  row,
                  3,
                  2 * n_blocks + block,
                  axes.normal + (-tan_bedding) * axes.along,
                  {0., 0.});
        add_loads(system, row, 3, chain, block, corners, pivot);
      }
    const std::vector<double> unknowns = system.solve();
    RotatedChainSolution      solution;
    for (unsigned int block = 0; block < n_blocks; ++block)
      {
        solution.lateral_force.push_back(unknowns[block]);
        solution.joint_shear.push_back(unknowns[n_blocks + block]);
        solution.normal_force.push_back(unknowns[2 * n_blocks + block]);
        solution.normal_force_offset.push_back(0.);
      }
    return solution;
  }

  RotatedChainSolution
  solve_rotated_chain_with_joint_slip(const Analytic::BlockChain &chain)
  {
    const unsigned int n_blocks     = chain.n_blocks();
    const double       tan_bedding  = std::tan(chain.bedding_friction);
    const double       tan_vertical = std::tan(chain.vertical_friction);
    // Unknowns: Q_i at i, N_i at n + i.
    DenseSystem system(2 * n_blocks);
    for (unsigned int block = 0; block < n_blocks; ++block)
      {
        const unsigned int row     = 2 * block;
        const BlockFrame   axes    = frame(chain.inclination[block]);
        const BlockPoints  corners = points(chain, axes);
        add_force(system,
                  row,
                  2,
                  block,
                  axes.along + (-tan_vertical) * axes.normal,
                  {0., 0.});
        if (block > 0)
          {
            const BlockFrame away_axes = frame(chain.inclination[block - 1]);
            add_force(system,
                      row,
                      2,
                      block - 1,
                      (-1.) * away_axes.along + tan_vertical * away_axes.normal,
                      {0., 0.});
          }
        add_force(system,
                  row,
                  2,
                  n_blocks + block,
                  axes.normal + (-tan_bedding) * axes.along,
                  {0., 0.});
        add_loads(system, row, 2, chain, block, corners, {0., 0.});
      }
    const std::vector<double> unknowns = system.solve();
    RotatedChainSolution      solution;
    for (unsigned int block = 0; block < n_blocks; ++block)
      {
        const double lateral_force = unknowns[block];
        const double normal_force  = unknowns[n_blocks + block];
        solution.lateral_force.push_back(lateral_force);
        solution.joint_shear.push_back(lateral_force * tan_vertical);
        solution.normal_force.push_back(normal_force);

        // Moments of all known forces about the face-side base corner;
        // the base friction passes through it, N_i balances the rest.
        const BlockFrame  axes    = frame(chain.inclination[block]);
        const BlockPoints corners = points(chain, axes);
        const Vector2     pivot   = corners.face_base;
        double            rest =
          moment((-1.) * pivot,
                 lateral_force * axes.along +
                   (-lateral_force * tan_vertical) * axes.normal) +
          moment(corners.centroid + (-1.) * pivot, {0., -chain.weight[block]}) +
          moment(corners.support_point + (-1.) * pivot,
                 {0., -chain.support_load[block]});
        if (block > 0)
          {
            const BlockFrame away_axes = frame(chain.inclination[block - 1]);
            const double     incoming  = unknowns[block - 1];
            rest += moment(corners.away_top + (-1.) * pivot,
                           (-incoming) * away_axes.along +
                             (incoming * tan_vertical) * away_axes.normal);
          }
        // N n applied at s along the base: moment s N (along x normal = 1).
        const double lever_from_face_side = -rest / normal_force;
        solution.normal_force_offset.push_back(chain.block_width -
                                               lever_from_face_side);
      }
    return solution;
  }
} // namespace FloorBlock::AnalyticTest
