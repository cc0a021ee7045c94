#include <fem/face_values.h>

namespace FloorBlock::Fem
{
  template <int dim>
  dealii::FEFaceValues<dim>
  boundary_face_values(const dealii::Mapping<dim>        &mapping,
                       const dealii::FiniteElement<dim>  &fe,
                       const dealii::Quadrature<dim - 1> &quadrature)
  {
    return dealii::FEFaceValues<dim>(mapping,
                                     fe,
                                     quadrature,
                                     dealii::update_values |
                                       dealii::update_normal_vectors |
                                       dealii::update_JxW_values);
  }

  template <int dim>
  dealii::FEFaceValues<dim>
  boundary_face_values(const FeSpace<dim> &space)
  {
    return boundary_face_values(space.mapping(),
                                space.fe(),
                                space.face_quadrature());
  }

  template dealii::FEFaceValues<2>
  boundary_face_values(const dealii::Mapping<2> &,
                       const dealii::FiniteElement<2> &,
                       const dealii::Quadrature<1> &);
  template dealii::FEFaceValues<3>
  boundary_face_values(const dealii::Mapping<3> &,
                       const dealii::FiniteElement<3> &,
                       const dealii::Quadrature<2> &);
  template dealii::FEFaceValues<2>
  boundary_face_values(const FeSpace<2> &);
  template dealii::FEFaceValues<3>
  boundary_face_values(const FeSpace<3> &);
} // namespace FloorBlock::Fem
