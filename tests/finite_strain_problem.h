/*
 * A static finite-strain solid without contact for the tests of
 * Common::Physics::FiniteStrainSolid (tests/common): serial, Newton's
 * method on the operator's tangent with a direct solver, prescribed
 * displacements on chosen DoFs (homogeneous constraints on the increment),
 * an optional dead load, the augmented Lagrangian loop of exactly
 * incompressible laws, and reactions from the internal forces.
 */
#ifndef tests_finite_strain_problem_h
#define tests_finite_strain_problem_h

#include <common/materials/finite_strain_material.h>
#include <common/physics/finite_strain_solid.h>

#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace FiniteStrainTest
{
  using namespace dealii;

  template <int dim>
  class Problem
  {
  public:
    using Vector = TrilinosWrappers::MPI::Vector;

    /**
     * @param triangulation Mesh (reference configuration), kept by
     * reference.
     * @param degree Element degree.
     */
    Problem(const Triangulation<dim>                      &triangulation,
            const unsigned int                             degree,
            const Common::Materials::FiniteStrainMaterial &law,
            const Common::Physics::FiniteStrainParameters &parameters,
            const Common::Physics::Kinematics              kinematics =
              Common::Physics::Kinematics::cartesian)
      : fe(FE_Q<dim>(degree), dim)
      , mapping(degree)
      , dof_handler(triangulation)
    {
      dof_handler.distribute_dofs(fe);
      solid = std::make_unique<Common::Physics::FiniteStrainSolid<dim>>(
        mapping,
        fe,
        std::map<types::material_id,
                 const Common::Materials::FiniteStrainMaterial *>{{0, &law}},
        kinematics,
        parameters);
      DoFTools::map_dofs_to_support_points(mapping,
                                           dof_handler,
                                           support_points);
      const IndexSet all = complete_index_set(dof_handler.n_dofs());
      u.reinit(all, MPI_COMM_WORLD);
      external_force.reinit(all, MPI_COMM_WORLD);
    }

    /** Prescribe the DoFs of @p dofs; their target values at each load
     * come from @p target(dof, load). */
    void
    prescribe(
      const std::vector<types::global_dof_index>                   &dofs,
      const std::function<double(types::global_dof_index, double)> &target)
    {
      for (const auto dof : dofs)
        prescribed[dof] = target;
      rebuild();
    }

    /** Release every prescribed DoF for which @p release(dof) holds. */
    void
    release(const std::function<bool(types::global_dof_index)> &release)
    {
      for (auto it = prescribed.begin(); it != prescribed.end();)
        it = release(it->first) ? prescribed.erase(it) : std::next(it);
      rebuild();
    }

    /**
     * Solve at load factor @p load (prescribed values and the dead load
     * scaled by it), with the augmentation loop of incompressible laws;
     * commit on success. Returns the Newton iterations, or -1.
     * @param residual_norms If given, the relative residual of every
     * iteration.
     */
    int
    solve(const double load, std::vector<double> *residual_norms = nullptr)
    {
      // The increments of the prescribed DoFs, applied by the first Newton
      // iteration through the tangent of the last accepted state (tangent
      // predictor).
      prescribed_increment.reinit(complete_index_set(dof_handler.n_dofs()),
                                  MPI_COMM_WORLD);
      for (const auto &[dof, target] : prescribed)
        prescribed_increment(dof) = target(dof, load) - u(dof);
      int total = 0;
      for (unsigned int augmentation = 0; augmentation < 50; ++augmentation)
        {
          const int iterations = newton(load, residual_norms);
          if (iterations < 0)
            return -1;
          total += iterations;
          last_dilatation_error = solid->augment(dof_handler, u);
          if (last_dilatation_error <= solid->incompressibility_tolerance())
            {
              solid->commit(dof_handler, u);
              n_augmentations = augmentation;
              return total;
            }
        }
      return -1;
    }

    /** The internal forces at the current displacement (N). */
    Vector
    internal_force() const
    {
      Vector f(complete_index_set(dof_handler.n_dofs()), MPI_COMM_WORLD);
      AffineConstraints<double> none;
      none.close();
      solid->assemble_internal_force(dof_handler, none, u, f);
      f.compress(VectorOperation::add);
      return f;
    }

    /** Sum of the internal forces over @p dofs, each weighted. */
    double
    reaction(const std::vector<std::pair<types::global_dof_index, double>>
               &weighted_dofs) const
    {
      const Vector f   = internal_force();
      double       sum = 0.;
      for (const auto &[dof, weight] : weighted_dofs)
        sum += weight * f(dof);
      return sum;
    }

    /** The DoFs of component @p c whose support point satisfies
     * @p where. */
    std::vector<types::global_dof_index>
    dofs(const unsigned int                             c,
         const std::function<bool(const Point<dim> &)> &where) const
    {
      std::vector<types::global_dof_index> result;
      for (types::global_dof_index i = 0; i < dof_handler.n_dofs(); ++i)
        if (component(i) == c && where(support_points.at(i)))
          result.push_back(i);
      return result;
    }

    /** The vector component of DoF @p i. */
    unsigned int
    component(const types::global_dof_index i) const
    {
      return dof_components.empty() ? compute_components().at(i) :
                                      dof_components.at(i);
    }

    FESystem<dim>                                            fe;
    MappingQ<dim>                                            mapping;
    DoFHandler<dim>                                          dof_handler;
    std::unique_ptr<Common::Physics::FiniteStrainSolid<dim>> solid;
    std::map<types::global_dof_index, Point<dim>>            support_points;
    Vector                                                   u;
    /** Increments of the prescribed DoFs still to apply (mm). */
    Vector prescribed_increment;
    /** Dead load at load factor 1 (N), added scaled by the load. */
    Vector external_force;
    double newton_tolerance      = 1e-10;
    double last_dilatation_error = 0.;
    /** Largest force norm of the run (N), the scale of the residual. */
    double       force_scale     = 0.;
    unsigned int n_augmentations = 0;

  private:
    AffineConstraints<double>      constraints;
    TrilinosWrappers::SparseMatrix matrix;
    std::map<types::global_dof_index,
             std::function<double(types::global_dof_index, double)>>
                                      prescribed;
    mutable std::vector<unsigned int> dof_components;

    void
    rebuild()
    {
      constraints.clear();
      for (const auto &[dof, f] : prescribed)
        constraints.add_line(dof);
      constraints.close();
      DynamicSparsityPattern pattern(dof_handler.n_dofs());
      DoFTools::make_sparsity_pattern(dof_handler, pattern);
      matrix.reinit(complete_index_set(dof_handler.n_dofs()),
                    complete_index_set(dof_handler.n_dofs()),
                    pattern,
                    MPI_COMM_WORLD);
    }

    const std::vector<unsigned int> &
    compute_components() const
    {
      dof_components.assign(dof_handler.n_dofs(), 0);
      std::vector<types::global_dof_index> indices(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(indices);
          for (unsigned int i = 0; i < indices.size(); ++i)
            dof_components[indices[i]] = fe.system_to_component_index(i).first;
        }
      return dof_components;
    }

    /** Newton's method at fixed multipliers; iterations or -1. The
     * relative residual is the residual norm over the norm of the
     * reactions plus the dead load. */
    int
    newton(const double load, std::vector<double> *residual_norms)
    {
      const IndexSet all = complete_index_set(dof_handler.n_dofs());
      Vector         residual(all, MPI_COMM_WORLD), update(all, MPI_COMM_WORLD);
      for (unsigned int it = 0; it < 30; ++it)
        {
          matrix               = 0.;
          residual             = 0.;
          const bool predictor = it == 0 && prescribed_increment.l2_norm() > 0.;
          AffineConstraints<double> none;
          none.close();
          // The predictor needs the unconstrained columns of the prescribed
          // DoFs: assemble without constraints, then eliminate them.
          solid->assemble_system(dof_handler,
                                 predictor ? none : constraints,
                                 u,
                                 matrix,
                                 residual);
          residual.add(load, external_force);
          matrix.compress(VectorOperation::add);
          residual.compress(VectorOperation::add);
          if (predictor)
            {
              Vector K_dp(residual);
              matrix.vmult(K_dp, prescribed_increment);
              residual.add(-1., K_dp);
              std::vector<types::global_dof_index> rows;
              for (const auto &[dof, f] : prescribed)
                rows.push_back(dof);
              matrix.clear_rows(rows, 1.);
            }
          for (const auto &[dof, f] : prescribed)
            residual(dof) = 0.;
          residual.compress(VectorOperation::insert);
          // Relative to the largest forces of the run so far, so that a
          // load-free state (after a release) has a scale too.
          force_scale        = std::max(force_scale, reaction_scale(load));
          const double scale = std::max(1e-300, force_scale);
          const double norm  = residual.l2_norm() / scale;
          if (residual_norms != nullptr)
            residual_norms->push_back(norm);
          if (!predictor && norm < newton_tolerance)
            return it;
          SolverControl                  control(100, 1e-12, false, false);
          TrilinosWrappers::SolverDirect solver(control);
          solver.solve(matrix, update, residual);
          constraints.distribute(update);
          if (predictor)
            {
              // The solution's columns of the prescribed DoFs were kept in
              // the matrix: zero the update there and add the increments.
              for (const auto &[dof, f] : prescribed)
                update(dof) = prescribed_increment(dof);
              prescribed_increment = 0.;
            }
          u.add(1., update);
        }
      return -1;
    }

    /** Size of the forces: internal forces at the prescribed DoFs plus
     * the dead load (N). */
    double
    reaction_scale(const double load) const
    {
      const Vector f   = internal_force();
      double       sum = load * load * external_force.norm_sqr();
      for (const auto &[dof, target] : prescribed)
        sum += f(dof) * f(dof);
      return std::sqrt(sum);
    }
  };
  /**
   * Thick-walled cylinder as a quarter annulus about the origin (2D):
   * symmetry on x = 0 and y = 0, and the inner surface r = @p A moved
   * radially by @p radial_per_load times the load (mm). Returns the
   * inner DoFs weighted by the radial direction, whose reaction() is the
   * radial force on the inner surface (N per mm of depth).
   */
  inline std::vector<std::pair<types::global_dof_index, double>>
  prescribe_quarter_annulus(Problem<2>  &problem,
                            const double A,
                            const double radial_per_load)
  {
    problem.prescribe(
      problem.dofs(0, [](const Point<2> &x) { return std::abs(x[0]) < 1e-10; }),
      [](auto, double) { return 0.; });
    problem.prescribe(
      problem.dofs(1, [](const Point<2> &x) { return std::abs(x[1]) < 1e-10; }),
      [](auto, double) { return 0.; });
    std::vector<std::pair<types::global_dof_index, double>> radial;
    for (unsigned int c = 0; c < 2; ++c)
      {
        const auto inner = problem.dofs(c, [A](const Point<2> &x) {
          return std::abs(x.norm() - A) < 1e-8;
        });
        problem.prescribe(
          inner,
          [&problem, c, A, radial_per_load](const types::global_dof_index dof,
                                            const double load) {
            return load * radial_per_load * problem.support_points.at(dof)[c] /
                   A;
          });
        for (const auto dof : inner)
          radial.emplace_back(dof, problem.support_points.at(dof)[c] / A);
      }
    return radial;
  }
} // namespace FiniteStrainTest

#endif
