#include <common/contact/contact_parameters.h>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    void
    ContactParameters::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      {
        prm.declare_entry("Primary boundary id",
                          "0",
                          Patterns::Integer(0, 254),
                          "Boundary id of the primary surface, onto which "
                          "secondary points are projected. Dimensionless.");
        prm.declare_entry("Secondary boundary id",
                          "1",
                          Patterns::Integer(0, 254),
                          "Boundary id of the secondary surface, which "
                          "carries the Lagrange multipliers and where "
                          "pressures are reported. Dimensionless.");
        prm.declare_entry("Enforcement",
                          "lagrange multiplier",
                          Patterns::Selection("lagrange multiplier|penalty"),
                          "Enforcement of the normal contact condition: "
                          "'lagrange multiplier' (dual mortar multipliers, "
                          "exact, no user constant changes the answer) or "
                          "'penalty' (answer depends on 'Penalty "
                          "stiffness').");
        prm.declare_entry("Friction law",
                          "frictionless",
                          Patterns::Selection("frictionless|coulomb"),
                          "Tangential contact law: 'frictionless' or "
                          "'coulomb' (exact Coulomb friction with stick and "
                          "slip, no regularisation; Lagrange multipliers "
                          "only).");
        prm.declare_entry("Friction coefficient",
                          "0.0",
                          Patterns::Double(0.),
                          "Coulomb friction coefficient mu, used by "
                          "'coulomb' only. Dimensionless, >= 0.");
        prm.declare_entry("Penalty stiffness",
                          "1e6",
                          Patterns::Double(0.),
                          "Penalty enforcement only: contact pressure per "
                          "unit penetration. Units: MPa/mm (N/mm^3).");
        prm.declare_entry("NCP constant factor",
                          "1.0",
                          Patterns::Double(0., 1e3),
                          "Lagrange multipliers only: factor c_N in the "
                          "complementarity constant c = c_N E/h of the "
                          "semismooth Newton method (E: secondary Young's "
                          "modulus, h: local mesh size). Affects the "
                          "iteration path only. Dimensionless, > 0 and at "
                          "most 1000 (1e6 stalled the iteration of a "
                          "fuzzed input).");
        prm.declare_entry("Tangential NCP constant factor",
                          "0.5",
                          Patterns::Double(0., 1e3),
                          "Coulomb friction only: factor c_T in the "
                          "tangential complementarity constant c = c_T E/h "
                          "that weighs the slip increment against the "
                          "traction in the stick/slip decision. Values "
                          "below the normal factor make a node slip only "
                          "once its traction nears the bound, which avoids "
                          "stick/slip cycling where nearly every node "
                          "sticks. Affects the iteration path only. "
                          "Dimensionless, > 0 and at most 1000.");
        prm.declare_entry("Search distance",
                          "5.0",
                          Patterns::Double(0.),
                          "Secondary points whose initial normal gap to the "
                          "primary surface exceeds this distance are never "
                          "paired. Must exceed the largest closing of the "
                          "gap. Units: mm.");
        prm.declare_entry("Accelerate active set release",
                          "true",
                          Patterns::Bool(),
                          "When an iteration only opens points (a contact "
                          "zone larger than the solution), also open the "
                          "closed points that lie within the mirror image of "
                          "the opened band. An Aitken-type extrapolation of "
                          "the contact edge: the plain rule shrinks an "
                          "oversized zone only linearly. It is switched off "
                          "for the rest of the step as soon as it opens too "
                          "much. Affects the iteration path only.");
        prm.declare_entry(
          "Initial active set",
          "touching",
          Patterns::Selection("touching|nearest per body"),
          "Which secondary nodes the first active set closes. touching: "
          "every paired node that touches its partner (gap below 1e-8 of "
          "its face), so that a body held only by contact is held from the "
          "first iteration on. nearest per body: only the paired node "
          "nearest to each primary body (each rigid tool, or the meshed "
          "primary surface; the first node in the surface's order on "
          "ties), and in 3D the nodes of its line along z (the line of "
          "first contact of bodies extruded along z), for a body that "
          "rests on a flat tool and lifts off under load, where closing the "
          "whole touching zone would make the semismooth Newton method "
          "release it one node per iteration. Affects the iteration path "
          "only.");
        prm.declare_entry(
          "Rigid tool gap",
          "mortar",
          Patterns::Selection("mortar|nodal"),
          "The gap of a secondary node against an analytic rigid tool, "
          "with rows in the current configuration. mortar: the "
          "dual-weighted mean gap over the node's faces (Popp et al.), "
          "which sees the tool's curvature between the nodes: a closed "
          "node stands h^2/(12 R) off a tool of radius R (mm, h the face "
          "length), and a node next to a line contact may need a "
          "negative pressure. nodal: the signed distance of the node "
          "itself to its closest point on the tool (node to rigid "
          "surface), the contact force along the tool's normal there; the "
          "faces between closed nodes may cut into a curved tool by up to "
          "h^2/(8 R). Ignored for a meshed primary surface.");
        prm.declare_entry(
          "Configuration",
          "automatic",
          Patterns::Selection("automatic|reference|current"),
          "Where the mortar rows are paired and integrated: 'reference' "
          "(once, on the undeformed surfaces: small strain and small "
          "sliding), 'current' (again at every Newton iterate, on the "
          "deformed surfaces: finite strain, large sliding and rotation; "
          "needs 'Kinematics = finite strain' in subsection Solid), or "
          "'automatic' (current under finite-strain kinematics, reference "
          "otherwise).");
      }
      prm.leave_subsection();
    }



    void
    ContactParameters::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Contact");
      {
        primary_boundary_id   = prm.get_integer("Primary boundary id");
        secondary_boundary_id = prm.get_integer("Secondary boundary id");
        enforcement           = (prm.get("Enforcement") == "penalty" ?
                                   Enforcement::penalty :
                                   Enforcement::lagrange_multiplier);
        friction_law =
          (prm.get("Friction law") == "coulomb" ? FrictionLaw::coulomb :
                                                  FrictionLaw::frictionless);
        friction_coefficient = (friction_law == FrictionLaw::coulomb ?
                                  prm.get_double("Friction coefficient") :
                                  0.);
        penalty_stiffness    = prm.get_double("Penalty stiffness");
        ncp_factor           = prm.get_double("NCP constant factor");
        tangential_ncp_factor =
          prm.get_double("Tangential NCP constant factor");
        search_distance         = prm.get_double("Search distance");
        accelerate_release      = prm.get_bool("Accelerate active set release");
        initial_active_set      = prm.get("Initial active set") == "touching" ?
                                    InitialActiveSet::touching :
                                    InitialActiveSet::nearest_per_body;
        rigid_tool_gap          = prm.get("Rigid tool gap") == "nodal" ?
                                    RigidToolGap::nodal :
                                    RigidToolGap::mortar;
        const std::string where = prm.get("Configuration");
        configuration = where == "current"   ? ContactConfiguration::current :
                        where == "reference" ? ContactConfiguration::reference :
                                               ContactConfiguration::automatic;
      }
      prm.leave_subsection();
      AssertThrow(primary_boundary_id != secondary_boundary_id,
                  ExcMessage("Contact: primary and secondary boundary ids "
                             "must differ."));
      AssertThrow(penalty_stiffness > 0.,
                  ExcMessage("Contact: 'Penalty stiffness' must be "
                             "positive."));
      AssertThrow(tangential_ncp_factor > 0.,
                  ExcMessage("Contact: 'Tangential NCP constant factor' "
                             "must be positive."));
      AssertThrow(ncp_factor > 0.,
                  ExcMessage("Contact: 'NCP constant factor' must be "
                             "positive."));
      AssertThrow(friction_law == FrictionLaw::frictionless ||
                    enforcement == Enforcement::lagrange_multiplier,
                  ExcMessage("Contact: 'coulomb' friction needs 'Enforcement "
                             "= lagrange multiplier'."));
      AssertThrow(search_distance > 0.,
                  ExcMessage("Contact: 'Search distance' must be positive."));
    }



    bool
    ContactParameters::in_current_configuration(const bool finite_strain) const
    {
      AssertThrow(configuration != ContactConfiguration::current ||
                    finite_strain,
                  ExcMessage("Contact: 'Configuration = current' needs "
                             "'Kinematics = finite strain' in subsection "
                             "Solid."));
      return configuration == ContactConfiguration::current ||
             (configuration == ContactConfiguration::automatic &&
              finite_strain);
    }
  } // namespace Contact
} // namespace Common
