#pragma once

#include <contact/contact_problem.h>
#include <geometry/end_faces.h>

namespace FloorBlock::Scene
{
  /**
   * @brief The contact problem of the 3D assembly swept along the face
   * (Geometry::extrude_assembly) from the 2D problem of the same scene.
   *
   * Everything keeps its id and its x-y part, with z = 0 added: elastic
   * laws (same Lamé constants), densities, gravity and the true vertical
   * `down` (y is up in 3D too; Fem::ElasticModel's default -e_z would
   * be wrong), support pressures, joints and their rigid planes, the
   * uplift (every cross-section moves as in 2D, u_z = 0). A support that
   * holds every in-plane component (the face block's outer side and
   * bottom, the base bottom) holds u_z as well; one that holds only some
   * leaves u_z free. @p end_faces adds u_z = 0 on Ids::end_face_near and
   * Ids::end_face_far (plane strain) or nothing (free).
   */
  Contact::ContactProblem<3>
  swept_contact_problem(const Contact::ContactProblem<2> &plane,
                        const Geometry::EndFaces          end_faces);
} // namespace FloorBlock::Scene
