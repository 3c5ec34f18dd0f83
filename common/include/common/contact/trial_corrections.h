#ifndef common_contact_trial_corrections_h
#define common_contact_trial_corrections_h

/**
 * @file trial_corrections.h
 * @brief The difference between the constraints that condense the contact
 * multipliers and the full linearisation of the contact conditions, where
 * the mortar rows follow the configuration.
 */

#include <deal.II/base/types.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <map>
#include <utility>
#include <vector>

namespace Common
{
  namespace Contact
  {
    /**
     * @brief The linearised contact condition of one closed node's DoF, as
     * the full derivative of the weighted gap gives it
     * (ContactGeometry::weighted_gap_derivative()), less the constraint
     * that DualLagrangeEnforcement::add_constraints() writes from the
     * fixed rows' gradient, both solved for the same DoF.
     *
     * The Newton increment must satisfy the first (the trial side of the
     * condensed system, P_G), while the second (P_B) keeps the contact
     * forces distributed by the fixed rows, as the residual distributes
     * them (its test side): the system is P_B^T A P_G, and its converged
     * state that of the constraints written.
     */
    struct TrialCorrection
    {
      /** The constrained DoF. */
      dealii::types::global_dof_index dof;
      /** Differences of the coefficients of the other DoFs
       * (dimensionless). */
      std::vector<std::pair<dealii::types::global_dof_index, double>> entries;
      /** Difference of the inhomogeneities (mm). */
      double inhomogeneity;
    };



    /**
     * @brief The TrialCorrections of one Newton iteration, by DoF.
     */
    class TrialCorrections
    {
    public:
      /** @brief Forget every correction. */
      void
      clear();

      /** @brief Add the correction of a DoF that has none yet. */
      void
      add(TrialCorrection &&correction);

      /** @brief True if there is no correction. */
      bool
      empty() const;

      /** @brief Every correction, in the order added. */
      const std::vector<TrialCorrection> &
      all() const;

      /** @brief The correction of DoF @p dof, or null. */
      const TrialCorrection *
      find(const dealii::types::global_dof_index dof) const;

      /**
       * @brief Move a local block of the tangent, whose columns act on the
       * increments of @p column_dofs, from the written constraints' trial
       * space to the full linearisation's: for each column of a corrected
       * DoF, add its entries times the correction's coefficients to the
       * columns of their DoFs (appended to @p column_dofs and @p matrix
       * where new), and its entries times the correction's inhomogeneity
       * to @p rhs, with the sign of a right-hand side (minus).
       * @param[in,out] column_dofs The columns' DoFs.
       * @param[in,out] matrix Rows x column_dofs.size().
       * @param[in,out] rhs The rows' right-hand side.
       */
      void
      extend_columns(std::vector<dealii::types::global_dof_index> &column_dofs,
                     dealii::FullMatrix<double>                   &matrix,
                     dealii::Vector<double>                       &rhs) const;

    private:
      std::vector<TrialCorrection>                            corrections;
      std::map<dealii::types::global_dof_index, unsigned int> index;
    };
  } // namespace Contact
} // namespace Common

#endif
