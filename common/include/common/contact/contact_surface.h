/**
 * @file contact_surface.h
 * A contact surface: the boundary faces with one boundary id, their nodes
 * (support points of the displacement element) with DoF indices, and the
 * face geometry as the isoparametric interpolation of the node positions.
 * Geometry only: no gaps, no pressures, no enforcement.
 */
#ifndef common_contact_contact_surface_h
#define common_contact_contact_surface_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/point.h>
#include <deal.II/base/scalar_polynomials_base.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include <array>
#include <vector>

namespace Common
{
  namespace Contact
  {
    /**
     * @brief One node of a contact surface: a support point of the
     * displacement element on the surface.
     */
    template <int dim>
    struct SurfaceNode
    {
      /** Position in the reference configuration (mm). */
      dealii::Point<dim> reference_position;
      /** Position in the current configuration (mm). */
      dealii::Point<dim> position;
      /** Global DoF index of each displacement component. */
      std::array<dealii::types::global_dof_index, dim> dofs;
      /** Averaged outward unit normal in the current configuration. */
      dealii::Tensor<1, dim> normal;
      /** Components c for which the node lies where the surface meets a
       * symmetry plane normal to e_c (ContactSurface::symmetrize_normals()):
       * its normal has no component along e_c. */
      std::array<bool, dim> on_symmetry_plane{};
    };

    /**
     * @brief One boundary face of a contact surface.
     */
    template <int dim>
    struct SurfaceFace
    {
      typename dealii::DoFHandler<dim>::active_cell_iterator cell;
      unsigned int                                           face_no;
      /** Indices (in the scalar base element) of the face's shape
       * functions. */
      std::vector<unsigned int> shape_indices;
      /** Surface node of each face shape function. */
      std::vector<unsigned int> nodes;
      /** +1 or -1: makes the normal computed from the tangents point out of
       * the body. */
      double orientation;
    };

    /**
     * @brief The faces with a given boundary id, with nodes and geometry.
     *
     * Face coordinates eta lie in [0,1]^(dim-1). The geometry is
     * \f$x(\eta) = \sum_a N_a(\eta)\,x_a\f$ with the element's own shape
     * functions: exact for an isoparametric MappingQ of the element degree.
     */
    template <int dim>
    class ContactSurface
    {
    public:
      /**
       * @brief Collect the faces of @p boundary_id and their nodes.
       * @param[in] dof_handler Vector-valued FE_Q (FESystem of dim equal
       * scalar elements).
       * @param[in] mapping Gives the support point positions.
       * @param[in] boundary_id Boundary id of the surface.
       * Throws if no face carries @p boundary_id.
       */
      ContactSurface(const dealii::DoFHandler<dim>   &dof_handler,
                     const dealii::Mapping<dim>      &mapping,
                     const dealii::types::boundary_id boundary_id);

      /** @brief Number of faces. */
      unsigned int
      n_faces() const;

      /** @brief Number of nodes. */
      unsigned int
      n_nodes() const;

      /** @brief Face @p f. */
      const SurfaceFace<dim> &
      face(const unsigned int f) const;

      /** @brief Node @p n. */
      const SurfaceNode<dim> &
      node(const unsigned int n) const;

      /** @brief Shape values of the face's nodes at @p eta. */
      void
      shape_values(const unsigned int            f,
                   const dealii::Point<dim - 1> &eta,
                   std::vector<double>          &values) const;

      /** @brief Shape values and derivatives d/d eta_k at @p eta. */
      void
      shape_values_and_derivatives(
        const unsigned int                       f,
        const dealii::Point<dim - 1>            &eta,
        std::vector<double>                     &values,
        std::vector<dealii::Tensor<1, dim - 1>> &derivatives) const;

      /** @brief Current position x(eta) on face @p f (mm). */
      dealii::Point<dim>
      point(const unsigned int f, const dealii::Point<dim - 1> &eta) const;

      /**
       * @brief Current position and tangents \f$\partial x/\partial\eta_k\f$
       * (mm) on face @p f.
       */
      dealii::Point<dim>
      point_and_tangents(
        const unsigned int                           f,
        const dealii::Point<dim - 1>                &eta,
        std::array<dealii::Tensor<1, dim>, dim - 1> &tangents) const;

      /** @brief Outward unit normal of face @p f at @p eta. */
      dealii::Tensor<1, dim>
      unit_normal(const unsigned int            f,
                  const dealii::Point<dim - 1> &eta) const;

      /** @brief Area element |dx/d eta| (mm^(dim-1)). */
      double
      jacobian(const unsigned int f, const dealii::Point<dim - 1> &eta) const;

      /** @brief Bounding box of face @p f's nodes, enlarged by
       * @p margin (mm) in every direction. */
      dealii::BoundingBox<dim>
      bounding_box(const unsigned int f, const double margin) const;

      /** @brief Typical size of face @p f (largest node distance, mm). */
      double
      face_size(const unsigned int f) const;

      /**
       * @brief Move the nodes to reference position + @p displacement (for
       * finite-strain scenes) and recompute nodal normals.
       * @param[in] displacement Vector with all surface DoFs readable.
       */
      template <typename VectorType>
      void
      update_positions(const VectorType &displacement);

      /**
       * @brief Move node @p n by @p shift (mm) and recompute the nodal
       * normals (for difference quotients of the geometry).
       */
      void
      move_node(const unsigned int n, const dealii::Tensor<1, dim> &shift);

      /**
       * @brief Take the symmetry planes of a model cut by them into the
       * nodal normals. A node whose displacement component c is held at
       * zero by a line of @p constraints without entries, while another
       * component is free, and whose faces all lie on one side of the plane
       * through it normal to e_c, sits where the surface meets a symmetry
       * plane: its normal drops component c (the average over its faces and
       * their mirror images, the normal of the uncut body). Kept when the
       * nodes move. Nodes with every component held, and nodes inside the
       * surface, are left alone.
       */
      void
      symmetrize_normals(const dealii::AffineConstraints<double> &constraints);

      /** @brief Scalar base element of the displacement element. */
      const dealii::FiniteElement<dim> &
      base_element() const;

    private:
      const dealii::FiniteElement<dim> &fe;
      /** The element's polynomial space (FE_Q), for evaluating all shape
       * functions at once; null for other elements. */
      const dealii::ScalarPolynomialsBase<dim> *poly_space;
      std::vector<SurfaceFace<dim>>             faces;
      std::vector<SurfaceNode<dim>>             nodes;
      /** Affine map of face coordinates into the unit cell, per face
       * number: origin and columns. */
      std::vector<dealii::Point<dim>>                          face_origin;
      std::vector<std::array<dealii::Tensor<1, dim>, dim - 1>> face_axes;

      dealii::Point<dim>
      unit_cell_point(const unsigned int            face_no,
                      const dealii::Point<dim - 1> &eta) const;

      void
      compute_nodal_normals();
    };
  } // namespace Contact
} // namespace Common

#endif
