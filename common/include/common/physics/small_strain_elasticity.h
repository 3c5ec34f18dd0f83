/**
 * @file small_strain_elasticity.h
 * Bulk terms of small-strain elasticity (plane strain or axisymmetric in
 * 2D, 3D solid): tangent matrix, residual and internal forces, one linear
 * elastic law per material id (body). No contact terms, no load stepping.
 *
 * Axisymmetric kinematics: the 2D coordinates are (r, z), r = x >= 0, with
 * the axis r = 0 as a boundary (where the caller prescribes u_r = 0); the
 * hoop strain \f$\varepsilon_{\theta\theta} = u_r/r\f$ joins the in-plane
 * strain, and every volume and surface integral carries the ring measure
 * \f$2\pi r\f$, so that forces are totals over the full circumference (N).
 */
#ifndef common_physics_small_strain_elasticity_h
#define common_physics_small_strain_elasticity_h

#include <common/materials/linear_elastic.h>
#include <common/physics/solid_operator.h>

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <boost/signals2/connection.hpp>

#include <map>
#include <memory>
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
     * once and kept; every later assembly only distributes them, with the
     * current constraints. They are computed again whenever the
     * triangulation changes (any refinement, coarsening or vertex motion
     * signals it) or the operator is used with another DoF handler or
     * number of DoFs.
     */
    template <int dim>
    class SmallStrainElasticity : public SolidOperator<dim>
    {
    public:
      /**
       * @param[in] mapping Geometry mapping (MappingQ of the element degree
       * for curved boundaries).
       * @param[in] fe Vector-valued element with dim components.
       * @param[in] materials Law per material id; every cell's id must be
       * present.
       * @param[in] kinematics Plane strain/3D or axisymmetric (2D only).
       */
      SmallStrainElasticity(
        const dealii::Mapping<dim>                    &mapping,
        const dealii::FiniteElement<dim>              &fe,
        const std::map<dealii::types::material_id,
                       Materials::LinearElastic<dim>> &materials,
        const Kinematics kinematics = Kinematics::cartesian);

      using typename SolidOperator<dim>::VectorType;
      using typename SolidOperator<dim>::MatrixType;

      /** @brief The kinematics of the model. */
      Kinematics
      kinematics() const override;

      /** @brief Small-strain elasticity is linear: true. */
      bool
      is_linear() const override;

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
      assemble_system(const dealii::DoFHandler<dim>           &dof_handler,
                      const dealii::AffineConstraints<double> &constraints,
                      const VectorType                        &u,
                      MatrixType                              &matrix,
                      VectorType &residual) override;

      /**
       * @brief Internal force vector \f$f_{int}(u) = \int B^T\sigma\f$ (N)
       * on locally owned cells, condensed with @p constraints (hanging-node
       * forces moved to their parents, constrained rows left zero) exactly
       * as the residual of assemble_system(). Not compressed here.
       */
      void
      assemble_internal_force(
        const dealii::DoFHandler<dim>           &dof_handler,
        const dealii::AffineConstraints<double> &constraints,
        const VectorType                        &u,
        VectorType                              &internal_force) override;

      /** @brief Forget the kept cell matrices. */
      void
      clear() override;

      /** @brief The Cauchy stress (StressPostprocessor). */
      std::vector<std::unique_ptr<dealii::DataPostprocessor<dim>>>
      output_postprocessors() const override;

      /** @brief The law of material id @p id. */
      const Materials::LinearElastic<dim> &
      material(const dealii::types::material_id id) const;

    private:
      const dealii::Mapping<dim>       &mapping;
      const dealii::FiniteElement<dim> &fe;
      const std::map<dealii::types::material_id, Materials::LinearElastic<dim>>
                                              materials;
      const Kinematics                        model_kinematics;
      const dealii::QGauss<dim>               quadrature;
      std::vector<dealii::FullMatrix<double>> cell_matrices;
      /** What the kept cell matrices were computed for. */
      const dealii::DoFHandler<dim>  *cached_dof_handler = nullptr;
      dealii::types::global_dof_index cached_n_dofs      = 0;
      /** Clears the cell matrices when the triangulation changes. */
      boost::signals2::scoped_connection triangulation_changed;

      /** Compute the cell matrices unless those kept belong to
       * @p dof_handler in its current state. */
      void
      ensure_cell_matrices(const dealii::DoFHandler<dim> &dof_handler);
    };



    /**
     * @brief Cauchy stress (MPa) for graphical output, from the
     * displacement gradient and the law of each cell. In 2D the stress is
     * the in-plane part of the plane-strain or axisymmetric stress (the
     * latter with the hoop strain in its trace; u_r/r is taken as
     * du_r/dr on the axis).
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
