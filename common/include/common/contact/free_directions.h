/**
 * @file free_directions.h
 * The directions in which each secondary node of a contact pair may move:
 * the tangent plane of its normal less the directions that Dirichlet
 * conditions (a symmetry plane, an axis) or hanging-node constraints fix,
 * and whether a normal condition can act on the node at all. Friction acts
 * only along the free tangents; on a symmetry plane of a 3D model, along
 * the line where plane and contact surface meet.
 *
 * Geometry only, evaluable without a mesh: built from the nodal normals
 * and the fixed displacement components of each node. No state, no law.
 */
#ifndef common_contact_free_directions_h
#define common_contact_free_directions_h

#include <common/contact/contact_surface.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/affine_constraints.h>

#include <array>
#include <vector>

namespace Common
{
  namespace Contact
  {
    /**
     * @brief An orthonormal basis of the plane (line in 2D) normal to the
     * unit vector @p normal: in 2D the tangent \f$(n_1, -n_0)\f$; in 3D the
     * coordinate direction least aligned with n, made orthogonal to it, and
     * the cross product of n with that.
     */
    template <int dim>
    std::vector<dealii::Tensor<1, dim>>
    tangent_basis(const dealii::Tensor<1, dim> &normal);

    /**
     * @brief Free tangent directions and normal freedom of every secondary
     * node.
     */
    template <int dim>
    class FreeDirections
    {
    public:
      /**
       * @brief Every node free in every direction: the free tangents are
       * tangent_basis() of its normal.
       * @param[in] normals Unit normal of each node (the nodal normals of
       * the mortar rows).
       */
      explicit FreeDirections(
        const std::vector<dealii::Tensor<1, dim>> &normals);

      /**
       * @brief Fix displacement component d of node @p j wherever
       * @p fixed[d] is true. The free tangents become the tangent
       * directions w with w_d = 0 for every fixed d: the tangent plane less
       * the span of the fixed unit vectors' tangential parts
       * (Gram-Schmidt). The node is normally free if a free component
       * carries a share of at least 1e-6 of its normal; not where every
       * component is fixed, nor where the fixed ones hold the normal (a
       * support along the normal).
       */
      void
      fix_components(const unsigned int j, const std::array<bool, dim> &fixed);

      /**
       * @brief fix_components() for every node of @p surface (whose nodes
       * are the nodes of this object, in order), with the components
       * that @p constraints constrain (Dirichlet conditions, hanging
       * nodes). Call once, after the constructor.
       */
      void
      fix_constrained_components(
        const ContactSurface<dim>               &surface,
        const dealii::AffineConstraints<double> &constraints);

      /**
       * @brief Give the nodes new normals (the contact geometry moved, in
       * the current configuration) and recompute their free tangents and
       * normal freedom with the components fixed so far.
       */
      void
      update_normals(const std::vector<dealii::Tensor<1, dim>> &normals);

      /** @brief Number of nodes. */
      unsigned int
      size() const;

      /** @brief Unit normal of node @p j. */
      const dealii::Tensor<1, dim> &
      normal(const unsigned int j) const;

      /** @brief Orthonormal basis of the tangent directions along which
       * node @p j may slip: the whole tangent plane (dim - 1 vectors) where
       * no component is fixed, fewer where some are, none on an axis. */
      const std::vector<dealii::Tensor<1, dim>> &
      free_tangents(const unsigned int j) const;

      /** @brief True if a free component of node @p j carries a share
       * of its normal (at least 1e-6), so that a normal condition can act
       * on the node's own displacement. */
      bool
      normally_free(const unsigned int j) const;

      /** @brief Part of @p x along the free tangents of node @p j (same
       * unit as x). */
      dealii::Tensor<1, dim>
      free_tangential_part(const unsigned int            j,
                           const dealii::Tensor<1, dim> &x) const;

    private:
      std::vector<dealii::Tensor<1, dim>>              normals;
      std::vector<std::vector<dealii::Tensor<1, dim>>> tangents;
      std::vector<bool>                                free_normally;
      /** The components fix_components() fixed, by node. */
      std::vector<std::array<bool, dim>> fixed_components;
    };
  } // namespace Contact
} // namespace Common

#endif
