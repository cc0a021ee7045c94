#include <geometry/ids.h>

#include <iomanip>
#include <sstream>
#include <vector>

namespace FloorBlock::Geometry::Ids
{
  namespace
  {
    std::string
    body_name(const unsigned int block)
    {
      return block == face_block_index ? std::string("face block") :
                                         "block " + std::to_string(block);
    }
  } // namespace

  std::string
  boundary_name(const dealii::types::boundary_id id,
                const unsigned int               n_blocks)
  {
    const unsigned int index = boundary_index(id);
    switch (boundary_kind(id))
      {
        case BoundaryKind::vertical_joint_free_side:
          return "vertical joint " + std::to_string(index) + ", " +
                 body_name(index) + " side";
        case BoundaryKind::vertical_joint_face_side:
          return "vertical joint " + std::to_string(index) + ", " +
                 body_name(index == n_blocks ? face_block_index : index + 1) +
                 " side";
        case BoundaryKind::bedding_block_side:
          return "bedding joint under " + body_name(index) + ", block bottom";
        case BoundaryKind::bedding_base_side:
          return "bedding joint under " + body_name(index) + ", base top";
        case BoundaryKind::floor_surface:
          return "floor surface, top of " + body_name(index);
        case BoundaryKind::footprint_surface:
          return "floor surface under the support footprint, top of " +
                 body_name(index) + " (3D)";
        case BoundaryKind::outer:
          switch (id)
            {
              case base_bottom:
                return "base bottom";
              case base_end_face_side:
                return "base end, face side";
              case base_end_free_side:
                return "base end, free side";
              case free_side_of_block_1:
                return "free side of block 1";
              case end_face_near:
                return "end face at z = 0 (3D)";
              case end_face_far:
                return "end face at z = face length (3D)";
              default:
                return "outer side of the face block";
            }
        default:
          return "unknown";
      }
  }

  std::string
  material_name(const dealii::types::material_id id)
  {
    if (id == face_block_material)
      return "face block";
    if (id == base_material)
      return "base (bedding layer)";
    if (id >= 1 && id <= max_n_blocks)
      return body_name(id);
    return "unknown";
  }

  std::string
  id_table(const unsigned int n_blocks)
  {
    constexpr int      id_width = 6;
    std::ostringstream table;
    const auto row = [&](const unsigned int id, const std::string &name) {
      table << "  " << std::setw(id_width) << id << "  " << name << '\n';
    };

    table << "Material ids (" << n_blocks << " blocks)\n";
    for (unsigned int block = 1; block <= n_blocks; ++block)
      row(block_material(block), material_name(block_material(block)));
    row(face_block_material, material_name(face_block_material));
    row(base_material, material_name(base_material));

    std::vector<dealii::types::boundary_id> boundaries;
    for (unsigned int joint = 1; joint <= n_blocks; ++joint)
      {
        boundaries.push_back(vertical_joint_free_side(joint));
        boundaries.push_back(vertical_joint_face_side(joint));
      }
    for (unsigned int block = 0; block <= n_blocks; ++block)
      {
        boundaries.push_back(bedding_block_side(block));
        boundaries.push_back(bedding_base_side(block));
      }
    for (unsigned int block = 0; block <= n_blocks; ++block)
      boundaries.push_back(floor_surface(block));
    for (unsigned int block = 1; block <= n_blocks; ++block)
      boundaries.push_back(footprint_surface(block));
    for (const dealii::types::boundary_id outer : {base_bottom,
                                                   base_end_face_side,
                                                   base_end_free_side,
                                                   free_side_of_block_1,
                                                   face_block_outer_side,
                                                   end_face_near,
                                                   end_face_far})
      boundaries.push_back(outer);

    table << "Boundary ids (= Gmsh physical curve tags; the end faces and "
             "footprint tops: 3D only)\n";
    for (const dealii::types::boundary_id id : boundaries)
      row(id, boundary_name(id, n_blocks));
    table << "Corner fillets: top fillets carry the id of the vertical side "
             "below them, bottom fillets the block-bottom id (4000+i).\n";
    return table.str();
  }
} // namespace FloorBlock::Geometry::Ids
