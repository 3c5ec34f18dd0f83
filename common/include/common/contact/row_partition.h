/**
 * @file row_partition.h
 * Which mortar rows (secondary nodes) of a contact pair one MPI rank works
 * on. The rank that owns the first DoF of a secondary node owns the node's
 * row: it decides the node's contact status, evaluates its complementarity
 * functions and contributes its contact terms to owned matrix and vector
 * rows. A rank also holds ghost rows: those of the secondary nodes that its
 * own cells need (their DoFs are on the rank's cells, or are the targets of
 * the constraints of such DoFs, such as the parents of a hanging node),
 * whose contact constraints enter the constraints of its cells. A ghost
 * row's status comes from its owner (ContactState::update_ghosts()). Rows
 * that a rank neither owns nor holds are never evaluated there; global
 * decisions over all rows are MPI collectives over communicator().
 *
 * Without a distribution (the default), every row is owned and the
 * communicator is MPI_COMM_SELF: the serial case.
 */
#ifndef common_contact_row_partition_h
#define common_contact_row_partition_h

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>

#include <map>
#include <vector>

namespace Common
{
  namespace Contact
  {
    /**
     * @brief The rows of a contact pair that one MPI rank owns and holds.
     */
    class RowPartition
    {
    public:
      /** @brief Every row owned, on MPI_COMM_SELF (serial). */
      RowPartition();

      /**
       * @brief Distribute the rows over the ranks of @p communicator
       * (collective).
       * @param[in] first_dofs First DoF of the secondary node of each row.
       * @param[in] needed Rows the rank needs besides its owned ones (a
       * ghost row each, if another rank owns it).
       * @param[in] owned_dofs The DoFs this rank owns; row j is owned if
       * first_dofs[j] is one of them.
       */
      RowPartition(
        const std::vector<dealii::types::global_dof_index> &first_dofs,
        const std::vector<bool>                            &needed,
        const dealii::IndexSet                             &owned_dofs,
        const MPI_Comm                                      communicator);

      /** @brief True if this rank owns row @p j (and decides it). */
      bool
      is_owned(const unsigned int j) const;

      /** @brief True if this rank holds row @p j: owns it or keeps it as a
       * ghost row. */
      bool
      is_held(const unsigned int j) const;

      /** @brief True if every row is owned here (serial). */
      bool
      owns_all() const;

      /** @brief The communicator of the collectives over the rows. */
      MPI_Comm
      communicator() const;

      /** @brief True if the communicator has more than one rank. */
      bool
      is_distributed() const;

      /** @brief Number of rows this rank owns, of @p n_rows. */
      unsigned int
      n_owned(const unsigned int n_rows) const;

      /** @brief Number of rows this rank holds (owned and ghost), of
       * @p n_rows. */
      unsigned int
      n_held(const unsigned int n_rows) const;

      /** @brief For each other rank, the rows owned here that it holds as
       * ghost rows (sorted). */
      const std::map<unsigned int, std::vector<unsigned int>> &
      ghost_holders() const;

    private:
      /** Role of each row: 0 not held, 1 ghost, 2 owned; empty if every
       * row is owned. */
      std::vector<unsigned char>                        role;
      MPI_Comm                                          comm;
      bool                                              distributed;
      std::map<unsigned int, std::vector<unsigned int>> holders;
    };



    inline bool
    RowPartition::is_owned(const unsigned int j) const
    {
      return role.empty() || role[j] == 2;
    }



    inline bool
    RowPartition::is_held(const unsigned int j) const
    {
      return role.empty() || role[j] != 0;
    }
  } // namespace Contact
} // namespace Common

#endif
