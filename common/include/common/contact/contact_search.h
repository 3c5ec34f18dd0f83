/**
 * @file contact_search.h
 * Geometry only: an R-tree over the bounding boxes of the faces of a
 * contact surface, and projections of points onto faces along a given
 * direction; nearest-point queries over a set of points (contact nodes).
 * No constitutive, penalty or multiplier information.
 */
#ifndef common_contact_contact_search_h
#define common_contact_contact_search_h

#include <common/contact/contact_surface.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/point.h>
#include <deal.II/numerics/rtree.h>

#include <utility>
#include <vector>

namespace Common
{
  namespace Contact
  {
    /**
     * @brief Result of projecting a point onto a face along a direction.
     */
    template <int dim>
    struct Projection
    {
      /** True if the Newton iteration converged. */
      bool converged = false;
      /** Face coordinates of the projected point (may lie outside
       * [0,1]^(dim-1): the face polynomial is extended). */
      dealii::Point<dim - 1> eta;
      /** Signed distance t along the direction: y(eta) = x + t d. */
      double distance = 0.;
      /** Projected point y(eta). */
      dealii::Point<dim> point;

      /** @brief True if eta lies in the face, up to @p tolerance. */
      bool
      inside(const double tolerance = 1e-10) const;
    };

    /**
     * @brief Finds candidate faces of a surface near a box, and projects
     * points onto faces.
     */
    template <int dim>
    class ContactSearch
    {
    public:
      /**
       * @param[in] surface Surface to search; must outlive this object.
       * @param[in] margin Enlargement of each face's bounding box (mm).
       */
      ContactSearch(const ContactSurface<dim> &surface, const double margin);

      /** @brief Rebuild the tree after the surface moved. */
      void
      update();

      /** @brief Faces whose enlarged bounding boxes intersect @p box. */
      std::vector<unsigned int>
      faces_near(const dealii::BoundingBox<dim> &box) const;

      /**
       * @brief Project @p x onto face @p f along @p direction: solve
       * \f$y(\eta) = x + t\,d\f$ for (eta, t) by Newton's method.
       */
      static Projection<dim>
      project_along(const ContactSurface<dim>    &surface,
                    const unsigned int            f,
                    const dealii::Point<dim>     &x,
                    const dealii::Tensor<1, dim> &direction);

      /**
       * @brief Inverse projection: find eta on face @p f such that @p y lies
       * on the line through x(eta) along the interpolated nodal normal
       * field \f$\sum_a N_a(\eta) n_a\f$ of the face, i.e.
       * \f$x(\eta) + t\,n(\eta) = y\f$.
       */
      static Projection<dim>
      project_along_normal_field(const ContactSurface<dim> &surface,
                                 const unsigned int         f,
                                 const dealii::Point<dim>  &y);

    private:
      const ContactSurface<dim>                                       &surface;
      const double                                                     margin;
      std::vector<std::pair<dealii::BoundingBox<dim>, unsigned int>>   boxes;
      dealii::RTree<std::pair<dealii::BoundingBox<dim>, unsigned int>> tree;
    };

    /**
     * @brief Nearest-point queries over a set of indexed points (an R-tree
     * of the points), with removal: O(log n) per query instead of a loop
     * over all points. The nearest point is the one of smallest
     * dealii::Point::distance(): the tree compares the same sums of
     * squares.
     */
    template <int dim>
    class NearestPoints
    {
    public:
      /**
       * @param[in] points Position of every index (mm).
       * @param[in] indices The indices in the set.
       */
      NearestPoints(const std::vector<dealii::Point<dim>> &points,
                    const std::vector<unsigned int>       &indices);

      /** @brief The index in the set, other than @p excluded, whose point
       * lies nearest to @p x; numbers::invalid_unsigned_int if there is
       * none. */
      unsigned int
      nearest(const dealii::Point<dim> &x,
              const unsigned int        excluded =
                dealii::numbers::invalid_unsigned_int) const;

      /** @brief Remove index @p i (which must be in the set). */
      void
      remove(const unsigned int i);

    private:
      const std::vector<dealii::Point<dim>>                      points;
      dealii::RTree<std::pair<dealii::Point<dim>, unsigned int>> tree;
    };
  } // namespace Contact
} // namespace Common

#endif
