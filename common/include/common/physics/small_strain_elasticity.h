/**
 * @file small_strain_elasticity.h
 * Bulk terms of small-strain elasticity (plane strain in 2D, 3D solid):
 * tangent matrix, residual and internal forces, one linear elastic law per
 * material id (body). No contact terms, no load stepping.
 */
#ifndef common_physics_small_strain_elasticity_h
#define common_physics_small_strain_elasticity_h

#include <common/materials/linear_elastic.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <map>
#include <vector>

namespace Common
{
  namespace Physics
  {
    /**
     * @brief Small-strain elasticity on a vector-valued FE_Q space, with a
     * linear elastic law chosen per cell by its material id.
     *
     * The problem is linear, so the cell stiffness matrices are computed
     * once and kept (for 2D problems, where they are small); every later
     * assembly only distributes them, with the current constraints.
     */
    template <int dim>
    class SmallStrainElasticity
    {
    public:
      /**
       * @param[in] mapping Geometry mapping (MappingQ of the element degree
       * for curved boundaries).
       * @param[in] fe Vector-valued element with dim components.
       * @param[in] materials Law per material id; every cell's id must be
       * present.
       */
      SmallStrainElasticity(
        const dealii::Mapping<dim>                    &mapping,
        const dealii::FiniteElement<dim>              &fe,
        const std::map<dealii::types::material_id,
                       Materials::LinearElastic<dim>> &materials);

      /**
       * @brief Assemble the tangent K and the residual
       * \f$r = -f_{int}(u)\f$ on locally owned cells, condensed with
       * @p constraints (which act on the Newton increment). External forces
       * are added by the caller.
       * @param[in] u Current displacement, with ghost entries (mm).
       * Matrix and residual are not compressed here, so that other terms
       * can be added first.
       */
      void
      assemble_system(const dealii::DoFHandler<dim>               &dof_handler,
                      const dealii::AffineConstraints<double>     &constraints,
                      const dealii::TrilinosWrappers::MPI::Vector &u,
                      dealii::TrilinosWrappers::SparseMatrix      &matrix,
                      dealii::TrilinosWrappers::MPI::Vector       &residual);

      /**
       * @brief Internal force vector \f$f_{int}(u) = \int B^T\sigma\f$ (N)
       * on locally owned cells, condensed with @p constraints (hanging-node
       * forces moved to their parents, constrained rows left zero) exactly
       * as the residual of assemble_system(). Not compressed here.
       */
      void
      assemble_internal_force(
        const dealii::DoFHandler<dim>               &dof_handler,
        const dealii::AffineConstraints<double>     &constraints,
        const dealii::TrilinosWrappers::MPI::Vector &u,
        dealii::TrilinosWrappers::MPI::Vector       &internal_force);

      /** @brief Forget the kept cell matrices (after the mesh changed). */
      void
      clear();

      /** @brief The law of material id @p id. */
      const Materials::LinearElastic<dim> &
      material(const dealii::types::material_id id) const;

    private:
      const dealii::Mapping<dim>       &mapping;
      const dealii::FiniteElement<dim> &fe;
      const std::map<dealii::types::material_id, Materials::LinearElastic<dim>>
                                              materials;
      const dealii::QGauss<dim>               quadrature;
      std::vector<dealii::FullMatrix<double>> cell_matrices;

      void
      compute_cell_matrices(const dealii::DoFHandler<dim> &dof_handler);
    };



    /**
     * @brief Cauchy stress (MPa) and von Mises stress for graphical output,
     * from the displacement gradient and the law of each cell. In 2D the
     * stress is the in-plane part of the plane-strain stress.
     */
    template <int dim>
    class StressPostprocessor : public dealii::DataPostprocessorTensor<dim>
    {
    public:
      /** @param[in] physics Supplies the law per material id. */
      explicit StressPostprocessor(const SmallStrainElasticity<dim> &physics);

      void
      evaluate_vector_field(
        const dealii::DataPostprocessorInputs::Vector<dim> &inputs,
        std::vector<dealii::Vector<double>>                &computed_quantities)
        const override;

    private:
      const SmallStrainElasticity<dim> &physics;
    };
  } // namespace Physics
} // namespace Common

#endif
