/**
 * @file mortar_coupling.h
 * Mortar (segment-to-segment) integration between a secondary and a
 * primary surface with dual Lagrange multiplier shape functions on the
 * secondary side. Produces, per secondary node j, the diagonal entry D_j,
 * the primary weights M_jk and the nodal normal n_j, from which the
 * weighted gap follows:
 * \f[ \tilde g_j = n_j\cdot\Big(\sum_k M_{jk}\,x_k - D_j\,x_j\Big),\qquad
 *     D_j = \int \psi_j N_j,\quad M_{jk} = \int \psi_j\,(N_k\circ\pi). \f]
 * Geometry and integration only: no enforcement, no material.
 *
 * References: B. Wohlmuth, SIAM J. Numer. Anal. 38 (2000) 989-1012;
 * A. Popp, M. Gee, W. Wall, IJNME 79 (2009) 1354-1391 (2D segmentation);
 * M. Puso, T. Laursen, CMAME 193 (2004) 601-629 and A. Popp et al.,
 * IJNME 83 (2010) 1428-1465 (3D segmentation in an auxiliary plane).
 */
#ifndef common_contact_mortar_coupling_h
#define common_contact_mortar_coupling_h

#include <common/contact/contact_search.h>
#include <common/contact/contact_surface.h>
#include <common/contact/rigid_surface.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <limits>
#include <utility>
#include <vector>

namespace Common
{
  namespace Contact
  {
    /**
     * @brief The row of the mortar operators that belongs to one secondary
     * node.
     */
    template <int dim>
    struct MortarRow
    {
      /** D_j: integral of the node's shape function (mm^(dim-1)). */
      double weight = 0.;
      /** Averaged outward unit normal of the secondary surface at j;
       * against analytic rigid surfaces in the current configuration
       * (MortarCoupling::set_tool_normals()) the direction in which the
       * weighted gap changes with the node's own displacement, the
       * dual-weighted inward normal of the surfaces at the partner points
       * (which on a coarse secondary face over a curved tool differs from
       * the face normal by the angle between them). The contact force and
       * the linearised normal condition act along it. */
      dealii::Tensor<1, dim> normal;
      /** (primary node k, M_jk in mm^(dim-1), or mm^2 if axisymmetric),
       * sorted by k. */
      std::vector<std::pair<unsigned int, double>> primary_weights;
      /** True if every face around j is fully covered by primary faces
       * within the search distance and j has a measure (D_j > 0; a
       * node without measure gets D_j = 0 exactly): only such nodes can
       * come into contact. */
      bool has_partner = false;
      /** Size of the largest face around j (mm). */
      double mesh_size = 0.;
      /** Gap at the node itself, along its normal, when the operators
       * were integrated (mm); +infinity if the normal misses the primary
       * surface. Decides which nodes touch at the start. */
      double nodal_gap = std::numeric_limits<double>::infinity();
      /** Weighted gap of the reference geometry,
       * \f$n_j\cdot(\sum_k M_{jk}X_k - D_j X_j)\f$ (mm^dim). */
      double reference_weighted_gap = 0.;
    };

    /**
     * @brief A node of the primary side as the mortar rows see it: its
     * reference position and its DoFs.
     */
    template <int dim>
    struct PrimaryNode
    {
      /** Position in the reference configuration (mm). */
      dealii::Point<dim> reference_position;
      /** Global DoF index of each displacement component. */
      std::array<dealii::types::global_dof_index, dim> dofs;
    };

    /**
     * @brief An analytic rigid surface as the primary side of mortar rows:
     * the surface (placed where it is now) and the reference node whose
     * DoFs carry its translation.
     */
    template <int dim>
    struct RigidPartner
    {
      /** The surface, placed in its current position. */
      const RigidSurface<dim> *surface = nullptr;
      /** DoFs of the reference node, one per component. */
      std::array<dealii::types::global_dof_index, dim> dofs;
      /** Current displacement of the reference node (mm): a partner point
       * x is stored as x less this, so that stored position plus
       * displacement is x. Zero in the reference configuration. */
      dealii::Tensor<1, dim> displacement;
    };

    /**
     * @brief Mortar operators D (diagonal) and M between two surfaces.
     */
    template <int dim>
    class MortarCoupling
    {
    public:
      /**
       * @brief Integrate D and M over the secondary surface.
       *
       * Each secondary face is cut into segments by the images of the
       * primary face boundaries, projected along the secondary normal
       * field; each segment is integrated with Gauss quadrature, so the
       * operators are exact for straight faces and the contact patch test
       * is passed exactly. In 3D the segments are the polygons in which
       * the projections of a secondary and a primary face onto an
       * auxiliary plane overlap (exact for plane faces).
       *
       * @param[in] secondary Secondary surface.
       * @param[in] primary Primary surface.
       * @param[in] search Search structure over @p primary.
       * @param[in] search_distance Points with |gap| above this are not
       * paired (mm).
       * @param[in] axisymmetric If true (2D only), the surfaces are
       * meridians of surfaces of revolution about the axis x = 0: every
       * integral, the dual basis included, carries the ring measure
       * \f$2\pi x\f$, so D and M are areas (mm^2) and the pressures of a
       * Lagrange-multiplier enforcement are forces per area.
       * @param[in] integrated_rows The rows to integrate, by secondary
       * node (all if empty), closed under the hanging-node condensation
       * (rows_to_integrate()): only the secondary faces that touch them
       * are paired. Every row gets its weight D_j; a row not integrated
       * has no partner.
       */
      void
      reinit(const ContactSurface<dim> &secondary,
             const ContactSurface<dim> &primary,
             const ContactSearch<dim>  &search,
             const double               search_distance,
             const bool                 axisymmetric    = false,
             const std::vector<bool>   &integrated_rows = {});

      /**
       * @brief Integrate D and the mortar rows against an analytic rigid
       * surface that moves with the displacement of one reference node.
       *
       * Each integration point x of a secondary face (a Gauss rule of
       * degree + 3 points, iterated over 4 sub-intervals per direction, as
       * the closest-point map of a profile with corners is not smooth) is
       * paired with the point $\pi(x)$ where the ray along the
       * interpolated secondary normal meets the rigid surface. A translation
       * of the rigid body moves every $\pi(x)$ alike, so row j becomes
       * $	ilde g_j = n_j\cdot(D_j(ar X_j + u_{ref}) - D_j(X_j + u_j))$
       * with $ar X_j = \int\psi_j\,\pi(x)/D_j$: one primary node per
       * row, at $ar X_j$, carrying the reference node's DoFs.
       * @param[in] reference_node_dofs DoFs of the reference node.
       * Other parameters as for the meshed reinit().
       */
      void
      reinit(const ContactSurface<dim> &secondary,
             const RigidSurface<dim>   &primary,
             const std::array<dealii::types::global_dof_index, dim>
                                     &reference_node_dofs,
             const double             search_distance,
             const bool               axisymmetric    = false,
             const std::vector<bool> &integrated_rows = {});

      /**
       * @brief Integrate D and the mortar rows against several analytic
       * rigid surfaces (the tools of a forming scene), each moving with its
       * own reference node. Each integration point pairs with the nearest
       * surface that the ray along the secondary normal meets (facing it);
       * row j gets one primary node per surface i it meets, numbered
       * j n + i for n surfaces, at the dual-weighted mean of its partner
       * points there, with \f$M_{ji}\f$ the share of \f$D_j\f$ that
       * surface i covers. With one surface this is the reinit() above.
       * @param[in] partners The surfaces and their reference nodes.
       * Other parameters as for the meshed reinit().
       */
      void
      reinit(const ContactSurface<dim>            &secondary,
             const std::vector<RigidPartner<dim>> &partners,
             const double                          search_distance,
             const bool                            axisymmetric    = false,
             const std::vector<bool>              &integrated_rows = {});

      /**
       * @brief The rows to integrate so that the rows marked in @p needed
       * (by node of @p secondary) are exact after
       * condense_hanging_nodes(): those rows, the hanging nodes among
       * their neighbours that a needed parent takes over, and the other
       * parents of those hanging nodes.
       */
      static std::vector<bool>
      rows_to_integrate(const ContactSurface<dim>               &secondary,
                        const dealii::AffineConstraints<double> &constraints,
                        const std::vector<bool>                 &needed);

      /** @brief True if row @p j was integrated by the last reinit(). */
      bool
      is_integrated(const unsigned int j) const;

      /**
       * @brief Let the meshed reinit() extend every free edge of the
       * primary surface (an edge that no other primary face shares) by
       * @p fraction of its face's parameter range, extrapolating the face.
       *
       * Where the edges of the two surfaces coincide (two bodies of one
       * material compressed together), an iterate that moves the primary
       * edge inwards by a round-off amount would leave the last secondary
       * face partly uncovered and drop its end node from contact. The
       * extension keeps it paired; at the converged state the extension
       * covers nothing that the surfaces do not share. Zero (the default)
       * integrates over the faces as they are.
       */
      void
      set_free_edge_extension(const double fraction);

      /**
       * @brief Whether rows against analytic rigid surfaces take the
       * surfaces' normal (MortarRow::normal) rather than the secondary
       * surface's. Right where the rows are integrated again at every
       * iterate (the current configuration), so that the weighted gap's
       * own gradient is the row's normal; in the reference configuration
       * the gap is linear in the displacement along the secondary normal,
       * as the small-strain theory has it. False by default.
       */
      void
      set_tool_normals(const bool use);

      /**
       * @brief Rows against analytic rigid surfaces from the node itself
       * (node to rigid surface) instead of its faces: row j pairs with
       * the nearest surface whose closest point to the node lies within
       * the search distance and faces the node, M_jk = D_j at that point,
       * so that the weighted gap is D_j times the node's signed distance
       * to the surface, and the row's normal is the surface's inward
       * normal there (with set_tool_normals()). Call before reinit().
       */
      void
      set_nodal_tool_gap(const bool use);

      /**
       * @brief Adapt the rows to the hanging nodes of the secondary
       * surface; call after reinit().
       *
       * A secondary node h whose displacement @p constraints interpolate
       * from other secondary nodes a (weights w_ha) is no DoF, and the
       * multiplier space loses its dual function \f$\psi_h\f$. Each parent
       * takes it over, and the basis is made biorthogonal to the
       * constrained trace functions \f$N'_a = N_a + \sum_h w_{ha} N_h\f$
       * again, locally:
       * \f[ \psi''_a = \frac{\Lambda_a}{D_a}\psi_a + \sum_h w_{ha}\psi_h
       *    - \sum_h w_{ha} D_h \sum_q w_{hq}\frac{\psi_q}{D_q},\qquad
       *    \Lambda_a = D_a + \sum_h w_{ha} D_h, \f]
       * which gives \f$\int\psi''_a N'_b = \Lambda_a\delta_{ab}\f$ and
       * \f$\sum_a\psi''_a = 1\f$ (a uniform pressure is represented
       * exactly). Parent a's row becomes the same combination of the
       * original rows: D''_a = \f$\Lambda_a\f$, M''_ak and the reference
       * weighted gap (with the true position of h, which on a curved
       * surface is not the interpolated one). The weighted gap is thus
       * exact for every displacement of the constrained space, and D stays
       * diagonal. The hanging node's row is emptied (no measure, no
       * partner); a parent is paired only if every row it draws on was.
       * A hanging node with a parent without measure (D = 0) keeps its
       * row.
       * @param[in] constraints Hanging-node (and Dirichlet) constraints,
       * closed; a node counts as hanging if all its components are
       * constrained and one of them is constrained, without inhomogeneity,
       * to the same component of other secondary nodes with weights
       * summing to one.
       * @return The number of hanging nodes whose rows were handed over.
       */
      unsigned int
      condense_hanging_nodes(
        const dealii::AffineConstraints<double> &constraints);

      /** @brief Number of rows (= secondary nodes). */
      unsigned int
      n_rows() const;

      /** @brief Row of secondary node @p j. */
      const MortarRow<dim> &
      row(const unsigned int j) const;

      /**
       * @brief Dual basis coefficients of secondary face @p f:
       * \f$\psi_a = \sum_b A_{ab} N_b\f$, with
       * \f$A = D\,M_e^{-1}\f$ and \f$\int\psi_a N_b = \delta_{ab}\int N_b\f$.
       */
      const dealii::FullMatrix<double> &
      dual_basis(const unsigned int f) const;

      /**
       * @brief Weighted gap \f$\tilde g_j\f$ (mm^dim) for the displacement
       * @p u, from reference positions plus displacements.
       */
      template <typename VectorType>
      double
      weighted_gap(const unsigned int j, const VectorType &u) const;

      /**
       * @brief Mean relative displacement of the primary surface with
       * respect to secondary node j,
       * \f$(\sum_k M_{jk} u_k - D_j u_j)/D_j\f$ (mm); zero for a node
       * without measure (D_j = 0).
       */
      template <typename VectorType>
      dealii::Tensor<1, dim>
      relative_displacement(const unsigned int j, const VectorType &u) const;

      /** @brief The secondary surface of the last reinit(). */
      const ContactSurface<dim> &
      secondary_surface() const;

      /** @brief The primary surface of the last reinit(); throws if the
       * primary side is a rigid surface. */
      const ContactSurface<dim> &
      primary_surface() const;

      /** @brief True if the primary side of the last reinit() is a set of
       * rigid surfaces (each primary node is a surface's reference node). */
      bool
      primary_is_rigid() const;

      /** @brief Number of primary nodes. */
      unsigned int
      n_primary_nodes() const;

      /** @brief Primary node @p k, to which MortarRow::primary_weights
       * refer. */
      const PrimaryNode<dim> &
      primary_node(const unsigned int k) const;

    private:
      /** 3D: integrate secondary face @p s against its primary faces by
       * polygon clipping, each primary face over its box of
       * @p parameter_boxes (primary_parameter_boxes()); calls
       * @p add_point(xi, JxW, m, eta_m) for every integration point.
       * @return The covered fraction of the face (1 if fully covered). */
      template <typename AddPoint>
      double
      integrate_3d_segments(
        const unsigned int        s,
        const ContactSearch<dim> &search,
        const double              search_distance,
        const std::vector<std::array<dealii::Point<dim - 1>, 2>>
                       &parameter_boxes,
        const AddPoint &add_point) const;

      /** The parents of each hanging node of @p secondary (secondary
       * nodes, with their interpolation weights; empty for other nodes). */
      static std::vector<std::vector<std::pair<unsigned int, double>>>
      hanging_parents(const ContactSurface<dim>               &secondary,
                      const dealii::AffineConstraints<double> &constraints);

      /** Which faces of the secondary surface touch an integrated row
       * (all if @p integrated_rows is empty); stores the rows. */
      std::vector<bool>
      select_faces(const std::vector<bool> &integrated_rows);

      /** Dual basis coefficients of secondary face @p s (stored) and
       * the integrals \f$\int N_a\f$ of its shape functions (@p De) and of
       * 1 (returned) with @p quadrature and the ring measure if
       * @p axisymmetric. */
      double
      compute_dual_basis(const unsigned int                 s,
                         const dealii::Quadrature<dim - 1> &quadrature,
                         const bool                         axisymmetric,
                         dealii::Vector<double>            &De);

      const ContactSurface<dim>              *secondary = nullptr;
      const ContactSurface<dim>              *primary   = nullptr;
      std::vector<PrimaryNode<dim>>           primary_nodes;
      std::vector<MortarRow<dim>>             rows;
      std::vector<dealii::FullMatrix<double>> dual_coefficients;
      /** The rows integrated by the last reinit(), by secondary node. */
      std::vector<bool> integrated;
      /** Extension of the free primary edges, as a fraction of a face's
       * parameter range (set_free_edge_extension()). */
      double free_edge_extension = 0.;
      /** Rows against rigid surfaces take their normal
       * (set_tool_normals()). */
      bool tool_normals = false;
      /** Rows against rigid surfaces from the node itself
       * (set_nodal_tool_gap()). */
      bool nodal_tool_gap = false;

      /** The parameter box of each primary face, extended past its free
       * edges by free_edge_extension, and in 3D past its edges on a
       * symmetry plane of both surfaces by at least a quarter of the face
       * (see symmetry_edge_extension in the source): lower and upper bound
       * per direction. */
      std::vector<std::array<dealii::Point<dim - 1>, 2>>
      primary_parameter_boxes() const;
    };
  } // namespace Contact
} // namespace Common

#endif
