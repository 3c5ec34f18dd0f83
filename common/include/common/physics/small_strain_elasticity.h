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

#include <map>
#include <vector>

namespace Common
{
  namespace Physics
  {
    /** How the 2D coordinates are read. */
    enum class Kinematics
    {
      /** Plane strain in 2D; the solid itself in 3D. */
      cartesian,
      /** Axisymmetric (2D only): x = r, y = z, integrals per full ring. */
      axisymmetric
    };

    /**
     * @brief Factor from the 2D (or 3D) measure to the physical one at
     * point @p x: \f$2\pi x_0\f$ (mm) for axisymmetric kinematics, 1
     * otherwise. Multiply the JxW of volume and boundary integrals
     * (external loads included) by it.
     */
    template <int dim>
    double
    measure_factor(const Kinematics kinematics, const dealii::Point<dim> &x);

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
       * @param[in] kinematics Plane strain/3D or axisymmetric (2D only).
       */
      SmallStrainElasticity(
        const dealii::Mapping<dim>                    &mapping,
        const dealii::FiniteElement<dim>              &fe,
        const std::map<dealii::types::material_id,
                       Materials::LinearElastic<dim>> &materials,
        const Kinematics kinematics = Kinematics::cartesian);

      /** @brief The kinematics of the model. */
      Kinematics
      kinematics() const;

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
      const Kinematics                        model_kinematics;
      const dealii::QGauss<dim>               quadrature;
      std::vector<dealii::FullMatrix<double>> cell_matrices;

      void
      compute_cell_matrices(const dealii::DoFHandler<dim> &dof_handler);
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
