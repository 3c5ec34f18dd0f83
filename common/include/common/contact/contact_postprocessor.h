/**
 * @file contact_postprocessor.h
 * Contact results from a converged state: the profile of pressure,
 * tangential traction, slip, gap and status at the secondary nodes, the
 * total contact force, the extent of the contact zone and the L2 error of
 * the pressure against a reference. Reads the enforcement's state; changes
 * nothing.
 */
#ifndef common_contact_contact_postprocessor_h
#define common_contact_contact_postprocessor_h

#include <common/contact/contact_enforcement.h>

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace Common
{
  namespace Contact
  {
    /**
     * @brief Result at one paired secondary node.
     */
    template <int dim>
    struct ContactPointResult
    {
      /** Secondary node index. */
      unsigned int node;
      /** Reference position (mm). */
      dealii::Point<dim> position;
      /** Normal pressure (MPa), >= 0 in compression. */
      double pressure;
      /** Tangential traction on the secondary surface along the tangent
       * t = (n_y, -n_x) in 2D (MPa). */
      double tangential_traction;
      /** Slip accumulated while in contact over the accepted load steps:
       * relative tangential displacement, primary minus secondary, along t
       * (mm). */
      double slip;
      /** Total relative tangential displacement since the undeformed
       * state, primary minus secondary, along t (mm). */
      double relative_displacement;
      /** Outward unit normal of the secondary surface. */
      dealii::Tensor<1, dim> normal;
      /** Tangential traction on the secondary surface, the vector in the
       * tangent plane (MPa); tangential_traction is its component along
       * tangent_of() the normal. */
      dealii::Tensor<1, dim> tangential_traction_vector;
      /** Slip accumulated in contact as a vector (mm), primary minus
       * secondary. */
      dealii::Tensor<1, dim> slip_vector;
      /** Total relative tangential displacement as a vector (mm), primary
       * minus secondary. */
      dealii::Tensor<1, dim> relative_displacement_vector;
      /** Mean normal gap g~_j / D_j (mm), negative when penetrating. */
      double gap;
      /** "open", "stick" or "slip" (a closed frictionless point slips). */
      std::string status;
    };

    /**
     * @brief Tangent of a 2D curve with normal n, t = (n_y, -n_x); in 3D
     * some unit vector orthogonal to n.
     */
    template <int dim>
    dealii::Tensor<1, dim>
    tangent_of(const dealii::Tensor<1, dim> &n);

    /**
     * @brief Results at every paired secondary node, sorted by the
     * coordinate @p axis of the reference position: evaluated by the rank
     * that owns each node and gathered on every rank (collective).
     * @param[in] bulk_residual f_ext - f_int (N, ghosted): gives the
     * tangential traction without friction (the traction that would be
     * needed to hold the node; zero at convergence).
     */
    template <int dim>
    std::vector<ContactPointResult<dim>>
    contact_profile(const MortarCoupling<dim>                   &coupling,
                    const ContactEnforcement<dim>               &enforcement,
                    const dealii::TrilinosWrappers::MPI::Vector &u,
                    const dealii::TrilinosWrappers::MPI::Vector &bulk_residual,
                    const unsigned int                           axis);

    /**
     * @brief Nodal fields of the contact state for graphical output, each
     * a name and a value per secondary node, keyed by the global DoF of the
     * node's first displacement component: "contact_pressure" (MPa),
     * "contact_status" (0 open, 1 stick, 2 slip), "tangential_traction"
     * (MPa, along tangent_of() the normal; in 3D its magnitude) and
     * "contact_slip" (slip accumulated in contact, mm, same convention).
     * With MPI, the nodes this rank holds (those of its own cells).
     */
    template <int dim>
    std::vector<
      std::pair<std::string, std::map<dealii::types::global_dof_index, double>>>
    contact_nodal_fields(const MortarCoupling<dim>     &coupling,
                         const ContactEnforcement<dim> &enforcement);

    /**
     * @brief Extent of the stick zone along a sorted profile: distance
     * from the first profile point to the midpoint between the last
     * sticking node of the run of stick nodes that starts at the first
     * closed node and the next node (mm); zero if that node does not
     * stick. If the next node is open (every closed node of the run
     * sticks), the stick zone is the contact zone: contact_extent().
     */
    template <int dim>
    double
    stick_extent(const std::vector<ContactPointResult<dim>> &profile,
                 const unsigned int                          axis);

    /**
     * @brief Total contact force on the secondary surface,
     * \f$\sum_j D_j(-\lambda_j n_j + t_j)\f$ with the tangential
     * tractions t_j of friction (N, or N/mm in plane strain): the owned
     * nodes' share, summed over the ranks (collective).
     */
    template <int dim>
    dealii::Tensor<1, dim>
    total_contact_force(const MortarCoupling<dim>     &coupling,
                        const ContactEnforcement<dim> &enforcement);

    /**
     * @brief Extent of the contact zone along a sorted profile, measured
     * from the profile's first point.
     *
     * The edge lies between the last loaded node and the next one. Near a
     * smooth contact edge the pressure behaves like
     * \f$p \propto \sqrt{a-x}\f$, so \f$p^2\f$ is extrapolated linearly
     * from the last two loaded nodes and the result is kept within that
     * node interval.
     * @return Distance from the first profile point to the edge (mm).
     */
    template <int dim>
    double
    contact_extent(const std::vector<ContactPointResult<dim>> &profile,
                   const unsigned int                          axis);

    /**
     * @brief L2 norm over the secondary surface of
     * \f$p_h - p_{ref}\f$, where \f$p_h = \sum_j \lambda_j N_j\f$
     * interpolates the nodal pressures (MPa mm^((dim-1)/2)). With MPI each
     * rank integrates over the faces of its own cells and the squares are
     * summed over the ranks (collective).
     * @param[out] reference_norm The L2 norm of p_ref over the same
     * surface.
     */
    template <int dim>
    double
    pressure_l2_error(
      const MortarCoupling<dim>                               &coupling,
      const ContactEnforcement<dim>                           &enforcement,
      const std::function<double(const dealii::Point<dim> &)> &reference,
      double                                                  &reference_norm);

    /**
     * @brief The section of a profile of a body extruded along z by the
     * plane z = @p z (dim = 3) as a plane-strain profile: the points there
     * (within 1e-8 of @p length_scale) with the x and y components of their
     * positions and vectors, and tangential_traction, slip and
     * relative_displacement the components of their vectors along
     * (n_y, -n_x, 0) normalised, the in-plane tangent that tangent_of()
     * gives in 2D. In 2D the profile unchanged.
     */
    template <int dim>
    std::vector<ContactPointResult<2>>
    plane_section(const std::vector<ContactPointResult<dim>> &profile,
                  const double                                z,
                  const double                                length_scale);

    /**
     * @brief Write the profile as CSV with the header
     * `x,pressure,tangential_traction,slip,relative_displacement,gap,status`,
     * where x is the coordinate @p axis (mm; MPa; MPa; mm; mm; mm).
     */
    template <int dim>
    void
    write_profile_csv(const std::string                          &filename,
                      const std::vector<ContactPointResult<dim>> &profile,
                      const unsigned int                          axis);
  } // namespace Contact
} // namespace Common

#endif
