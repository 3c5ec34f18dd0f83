#include <common/contact/row_partition.h>

#include <algorithm>

namespace Common
{
  namespace Contact
  {
    using namespace dealii;

    RowPartition::RowPartition()
      : comm(MPI_COMM_SELF)
      , distributed(false)
    {}



    RowPartition::RowPartition(
      const std::vector<types::global_dof_index> &first_dofs,
      const std::vector<bool>                    &needed,
      const IndexSet                             &owned_dofs,
      const MPI_Comm                              communicator)
      : comm(communicator)
      , distributed(Utilities::MPI::n_mpi_processes(communicator) > 1)
    {
      AssertDimension(first_dofs.size(), needed.size());
      const unsigned int n = first_dofs.size();
      role.assign(n, 0);
      IndexSet ghost_dofs(owned_dofs.size());
      for (unsigned int j = 0; j < n; ++j)
        if (owned_dofs.is_element(first_dofs[j]))
          role[j] = 2;
        else if (needed[j])
          {
            role[j] = 1;
            ghost_dofs.add_index(first_dofs[j]);
          }
      ghost_dofs.compress();
      if (!distributed)
        return;

      // Tell each owner which of its rows this rank keeps as ghosts.
      const std::vector<unsigned int> owners =
        Utilities::MPI::compute_index_owner(owned_dofs, ghost_dofs, comm);
      std::map<types::global_dof_index, unsigned int> owner_of;
      {
        unsigned int i = 0;
        for (auto it = ghost_dofs.begin(); it != ghost_dofs.end(); ++it, ++i)
          owner_of[*it] = owners[i];
      }
      std::map<unsigned int, std::vector<unsigned int>> requests;
      for (unsigned int j = 0; j < n; ++j)
        if (role[j] == 1)
          requests[owner_of.at(first_dofs[j])].push_back(j);
      holders = Utilities::MPI::some_to_some(comm, requests);
      for (auto &[rank, rows] : holders)
        std::sort(rows.begin(), rows.end());
    }



    bool
    RowPartition::owns_all() const
    {
      return role.empty() ||
             std::all_of(role.begin(), role.end(), [](const unsigned char r) {
               return r == 2;
             });
    }



    MPI_Comm
    RowPartition::communicator() const
    {
      return comm;
    }



    bool
    RowPartition::is_distributed() const
    {
      return distributed;
    }



    unsigned int
    RowPartition::n_owned(const unsigned int n_rows) const
    {
      if (role.empty())
        return n_rows;
      return std::count(role.begin(), role.end(), 2);
    }



    unsigned int
    RowPartition::n_held(const unsigned int n_rows) const
    {
      if (role.empty())
        return n_rows;
      return n_rows - std::count(role.begin(), role.end(), 0);
    }



    const std::map<unsigned int, std::vector<unsigned int>> &
    RowPartition::ghost_holders() const
    {
      return holders;
    }
  } // namespace Contact
} // namespace Common
