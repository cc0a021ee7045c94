#include <common/atomic_file.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <postprocess/vtu_writer.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <type_traits>

namespace FloorBlock::Postprocess
{
  namespace
  {
    /** Value of the contact_state field away from contact nodes. */
    constexpr double no_contact_node = -1.;

    /**
     * Stress fields evaluated from the displacement gradient per cell, 2D
     * plane strain: the in-plane components, the out-of-plane stress, von
     * Mises of the full state and the in-plane principal stresses.
     */
    class StressPostprocessor : public dealii::DataPostprocessor<2>
    {
    public:
      explicit StressPostprocessor(const Fem::ElasticModel<2> &model)
        : model(model)
      {}

      void
      evaluate_vector_field(
        const dealii::DataPostprocessorInputs::Vector<2> &inputs,
        std::vector<dealii::Vector<double>> &computed) const override
      {
        const auto                     cell = inputs.template get_cell<2>();
        const Material::ElasticLaw<2> &law = model.laws.at(cell->material_id());
        for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
          {
            dealii::Tensor<2, 2> gradient;
            for (unsigned int c = 0; c < 2; ++c)
              gradient[c] = inputs.solution_gradients[q][c];
            const dealii::SymmetricTensor<2, 2> strain =
              dealii::symmetrize(gradient);
            const dealii::SymmetricTensor<2, 2> stress = law.stress(strain);
            const double out_of_plane = law.out_of_plane_stress(strain);
            const double centre       = (stress[0][0] + stress[1][1]) / 2.;
            const double radius =
              std::sqrt(std::pow((stress[0][0] - stress[1][1]) / 2., 2) +
                        stress[0][1] * stress[0][1]);
            const double principal_max = centre + radius;
            const double principal_min = centre - radius;
            // von Mises of the full 3D plane-strain stress state.
            const double von_mises =
              std::sqrt(0.5 * (std::pow(principal_max - principal_min, 2) +
                               std::pow(principal_min - out_of_plane, 2) +
                               std::pow(out_of_plane - principal_max, 2)));
            computed[q](0) = stress[0][0];
            computed[q](1) = stress[1][1];
            computed[q](2) = stress[0][1];
            computed[q](3) = out_of_plane;
            computed[q](4) = von_mises;
            computed[q](5) = principal_max;
            computed[q](6) = principal_min;
          }
      }

      std::vector<std::string>
      get_names() const override
      {
        return {"stress_xx",
                "stress_yy",
                "stress_xy",
                "stress_zz",
                "von_mises",
                "principal_stress_max",
                "principal_stress_min"};
      }

      dealii::UpdateFlags
      get_needed_update_flags() const override
      {
        return dealii::update_gradients;
      }

    private:
      const Fem::ElasticModel<2> &model;
    };

    /**
     * 3D stress fields per cell: the six components and von Mises (the
     * principal stresses need an eigen-solve per point and are left out).
     */
    class SolidStressPostprocessor : public dealii::DataPostprocessor<3>
    {
    public:
      explicit SolidStressPostprocessor(const Fem::ElasticModel<3> &model)
        : model(model)
      {}

      void
      evaluate_vector_field(
        const dealii::DataPostprocessorInputs::Vector<3> &inputs,
        std::vector<dealii::Vector<double>> &computed) const override
      {
        const auto                     cell = inputs.template get_cell<3>();
        const Material::ElasticLaw<3> &law = model.laws.at(cell->material_id());
        for (unsigned int q = 0; q < inputs.solution_gradients.size(); ++q)
          {
            dealii::Tensor<2, 3> gradient;
            for (unsigned int c = 0; c < 3; ++c)
              gradient[c] = inputs.solution_gradients[q][c];
            const dealii::SymmetricTensor<2, 3> stress =
              law.stress(dealii::symmetrize(gradient));
            const dealii::SymmetricTensor<2, 3> deviator =
              dealii::deviator(stress);
            computed[q](0) = stress[0][0];
            computed[q](1) = stress[1][1];
            computed[q](2) = stress[2][2];
            computed[q](3) = stress[0][1];
            computed[q](4) = stress[1][2];
            computed[q](5) = stress[0][2];
            computed[q](6) = std::sqrt(1.5 * (deviator * deviator));
          }
      }

      std::vector<std::string>
      get_names() const override
      {
        return {"stress_xx",
                "stress_yy",
                "stress_zz",
                "stress_xy",
                "stress_yz",
                "stress_xz",
                "von_mises"};
      }

      dealii::UpdateFlags
      get_needed_update_flags() const override
      {
        return dealii::update_gradients;
      }

    private:
      const Fem::ElasticModel<3> &model;
    };

    /**
     * Writes the patches of @p data_out as the next increment of the
     * series in @p directory and updates the .pvd record.
     */
    template <int dim>
    void
    write_series_files(const dealii::DataOut<dim> &data_out,
                       const std::string          &directory,
                       const MPI_Comm              communicator,
                       std::vector<std::pair<double, std::string>> &records)
    {
      const unsigned int rank =
        dealii::Utilities::MPI::this_mpi_process(communicator);
      const unsigned int n_processes =
        dealii::Utilities::MPI::n_mpi_processes(communicator);
      // One process: solution-NNNN.vtu. Several: each writes its piece
      // solution-NNNN.RRRR.vtu and process 0 the record solution-NNNN.pvtu
      // that ParaView opens; solution.pvd lists one file per increment.
      std::ostringstream stem;
      stem << "solution-" << std::setw(4) << std::setfill('0')
           << records.size();
      const auto piece_name = [&](const unsigned int process) {
        std::ostringstream name;
        name << stem.str();
        if (n_processes > 1)
          name << "." << std::setw(4) << std::setfill('0') << process;
        return name.str() + ".vtu";
      };
      // The folder exists before any process writes into it.
      const int barrier = MPI_Barrier(communicator);
      AssertThrowMPI(barrier);
      const std::string path      = directory + "/" + piece_name(rank);
      const std::string temporary = temporary_name_for(path);
      {
        std::ofstream file(temporary);
        data_out.write_vtu(file);
      }
      commit_temporary_file(temporary, path);
      std::string listed = piece_name(0);
      if (n_processes > 1)
        {
          listed = stem.str() + ".pvtu";
          if (rank == 0)
            {
              std::vector<std::string> pieces;
              for (unsigned int process = 0; process < n_processes; ++process)
                pieces.push_back(piece_name(process));
              std::ostringstream record;
              data_out.write_pvtu_record(record, pieces);
              write_file_atomically(directory + "/" + listed, record.str());
            }
        }
      records.emplace_back(static_cast<double>(records.size()), listed);
      if (rank == 0)
        {
          std::ostringstream pvd;
          dealii::DataOutBase::write_pvd_record(pvd, records);
          write_file_atomically(directory + "/solution.pvd", pvd.str());
        }
    }
  } // namespace

  template <int dim>
  void
  write_vtu_increment(
    const Fem::FeSpace<dim>                            &space,
    const Fem::ElasticModel<dim>                       &model,
    const dealii::TrilinosWrappers::MPI::Vector        &solution,
    const std::vector<dealii::types::global_dof_index> &state_dofs,
    const std::vector<double>                          &states,
    const std::string                                  &directory,
    std::vector<std::pair<double, std::string>>        &records,
    const CellFields                                   &cell_fields)
  {
    const auto    &dof_handler  = space.dof_handler();
    const MPI_Comm communicator = dof_handler.get_communicator();
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      std::filesystem::create_directories(directory);
    // Every process writes the cells it owns, which read only its
    // locally relevant DoFs; the rest stay zero.
    dealii::Vector<double> displacement(solution.size());
    for (const auto i : space.locally_relevant_dofs())
      displacement(i) = solution(i);
    dealii::Vector<double> contact_state(dof_handler.n_dofs());
    contact_state = no_contact_node;
    for (unsigned int p = 0; p < state_dofs.size(); ++p)
      contact_state(state_dofs[p]) = states[p];
    dealii::Vector<float> material(
      dof_handler.get_triangulation().n_active_cells());
    for (const auto &cell : dof_handler.active_cell_iterators())
      material(cell->active_cell_index()) = cell->material_id();

    dealii::DataOut<dim> data_out;
    data_out.attach_dof_handler(dof_handler);
    const std::vector<
      dealii::DataComponentInterpretation::DataComponentInterpretation>
      vector_kind(
        dim, dealii::DataComponentInterpretation::component_is_part_of_vector);
    data_out.add_data_vector(displacement,
                             std::vector<std::string>(dim, "displacement"),
                             dealii::DataOut<dim>::type_dof_data,
                             vector_kind);
    // The state sits on each contact node's x DoF; the other components
    // are placeholders, named apart in 3D.
    std::vector<std::string> state_names{"contact_state"};
    for (unsigned int c = 1; c < dim; ++c)
      state_names.push_back(dim == 2 ?
                              std::string("contact_state_unused") :
                              "contact_state_unused_" + std::to_string(c));
    data_out.add_data_vector(contact_state, state_names);
    using Postprocessor = std::
      conditional_t<dim == 2, StressPostprocessor, SolidStressPostprocessor>;
    const Postprocessor stress(model);
    data_out.add_data_vector(displacement, stress);
    data_out.add_data_vector(material, "material_id");
    // DataOut keeps references: the vectors live until the files are written.
    std::vector<dealii::Vector<float>> extra_fields;
    extra_fields.reserve(cell_fields.size());
    for (const auto &[name, values] : cell_fields)
      {
        extra_fields.emplace_back(values.begin(), values.end());
        data_out.add_data_vector(extra_fields.back(), name);
      }
    data_out.build_patches(space.mapping(), space.degree());
    // deal.II defaults to best_compression, which took a quarter of the
    // default scene's run time in zlib; best_speed files are about 10 %
    // larger and written several times faster.
    dealii::DataOutBase::VtkFlags flags;
    flags.compression_level =
      dealii::DataOutBase::VtkFlags::ZlibCompressionLevel::best_speed;
    data_out.set_flags(flags);

    write_series_files(data_out, directory, communicator, records);
  }

  template void
  write_vtu_increment(const Fem::FeSpace<2> &,
                      const Fem::ElasticModel<2> &,
                      const dealii::TrilinosWrappers::MPI::Vector &,
                      const std::vector<dealii::types::global_dof_index> &,
                      const std::vector<double> &,
                      const std::string &,
                      std::vector<std::pair<double, std::string>> &,
                      const CellFields &);
  template void
  write_vtu_increment(const Fem::FeSpace<3> &,
                      const Fem::ElasticModel<3> &,
                      const dealii::TrilinosWrappers::MPI::Vector &,
                      const std::vector<dealii::types::global_dof_index> &,
                      const std::vector<double> &,
                      const std::string &,
                      std::vector<std::pair<double, std::string>> &,
                      const CellFields &);
} // namespace FloorBlock::Postprocess
