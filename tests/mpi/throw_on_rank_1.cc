// A run that fails on MPI rank 1 only, while rank 0 waits for it in a
// collective call: Common::IO::run_main() must report the error once and
// end every rank with a non-zero exit (tests/mpi/throw_on_rank_1.sh).

#include <common/io/run_main.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

int
main(int argc, char **argv)
{
  return Common::IO::run_main(
    argc,
    argv,
    "throw_on_rank_1",
    "fails on MPI rank 1 only",
    [](dealii::ParameterHandler &) {},
    [](const std::string &) {
      if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 1)
        AssertThrow(false, dealii::ExcMessage("thrown on rank 1 only"));
      // Rank 0 waits here for rank 1, which never comes.
      MPI_Barrier(MPI_COMM_WORLD);
    });
}
