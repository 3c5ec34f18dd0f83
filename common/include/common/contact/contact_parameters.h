/**
 * @file contact_parameters.h
 * The "Contact" subsection: which boundaries touch, how the normal
 * condition is enforced, and the search distance. Strings are turned into
 * enums once, here.
 */
#ifndef common_contact_contact_parameters_h
#define common_contact_contact_parameters_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

namespace Common
{
  namespace Contact
  {
    /** Values of the parameter "Enforcement" in subsection "Contact". */
    enum class Enforcement
    {
      /** Dual Lagrange multipliers, condensed; semismooth Newton. */
      lagrange_multiplier,
      /** Penalty on the mean gap of each secondary node. */
      penalty
    };

    /** Values of the parameter "Friction law" in subsection "Contact". */
    enum class FrictionLaw
    {
      /** No tangential traction. */
      frictionless,
      /** Exact Coulomb friction: stick while |t| < mu p, slip against the
       * relative motion with |t| = mu p otherwise. */
      coulomb
    };

    /** Values of the parameter "Configuration" in subsection "Contact". */
    enum class ContactConfiguration
    {
      /** Current under finite-strain kinematics, reference otherwise. */
      automatic,
      /** Rows paired and integrated once, in the undeformed configuration
       * (ReferenceMortarGeometry). */
      reference,
      /** Rows paired and integrated again at every Newton iterate, in the
       * deformed configuration (CurrentMortarGeometry). */
      current
    };

    /** Values of the parameter "Initial active set" in subsection
     * "Contact". */
    enum class InitialActiveSet
    {
      /** Every paired node that touches its partner is closed. */
      touching,
      /** Per primary body (each rigid tool; a meshed primary surface is
       * one body), only the paired node nearest to it is closed. */
      nearest_per_body
    };

    /** Values of the parameter "Rigid tool gap" in subsection "Contact". */
    enum class RigidToolGap
    {
      /** The dual-weighted mean gap of the node's faces (mortar). */
      mortar,
      /** The gap of the node itself, to its closest point on the tool. */
      nodal
    };

    /**
     * @brief One contact pair: a primary (projection target) and a secondary
     * (integration and multiplier) surface, with its enforcement.
     */
    struct ContactParameters
    {
      /** @brief Declare the entries of subsection "Contact". */
      static void
      declare_parameters(dealii::ParameterHandler &prm);

      /** @brief Read and check the entries of subsection "Contact". */
      void
      parse_parameters(dealii::ParameterHandler &prm);

      /**
       * @brief True if the rows are integrated in the current
       * configuration with the kinematics of the solid: 'current', or
       * 'automatic' with @p finite_strain. Throws for 'current' with
       * small-strain kinematics.
       */
      bool
      in_current_configuration(const bool finite_strain) const;

      /** @brief True if Coulomb friction with mu > 0 is enforced. */
      bool
      has_friction() const
      {
        return friction_law == FrictionLaw::coulomb &&
               friction_coefficient > 0.;
      }

      dealii::types::boundary_id primary_boundary_id;
      dealii::types::boundary_id secondary_boundary_id;
      Enforcement                enforcement;
      FrictionLaw                friction_law;
      /** Coulomb friction coefficient mu (dimensionless); 0 if
       * frictionless. */
      double friction_coefficient;
      /** Penalty stiffness (MPa/mm): pressure per unit penetration. */
      double penalty_stiffness;
      /** Factor c_N of the complementarity constant c = c_N E / h
       * (dimensionless). Changes the iteration path, never the answer. */
      double ncp_factor;
      /** Factor c_T of the tangential complementarity constant
       * c = c_T E / h (dimensionless); Coulomb friction only. Changes the
       * iteration path, never the answer. */
      double tangential_ncp_factor;
      /** Largest initial gap for which a secondary point is paired (mm). */
      double search_distance;
      /** Extrapolate pure release steps of the active set (path only). */
      bool accelerate_release;
      /** Where the mortar rows are integrated. */
      ContactConfiguration configuration = ContactConfiguration::automatic;
      /** Which nodes the first active set closes (iteration path only). */
      InitialActiveSet initial_active_set = InitialActiveSet::touching;
      /** The gap of a secondary node against an analytic rigid tool in the
       * current configuration. */
      RigidToolGap rigid_tool_gap = RigidToolGap::mortar;
    };
  } // namespace Contact
} // namespace Common

#endif
