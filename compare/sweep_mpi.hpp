// The MPI side of `ringvib sweep` (internal to compare/). Built with MPI when CMake finds
// it (RINGVIB_WITH_MPI); without it, launched() still recognizes an mpirun launch from
// the environment so that only one rank runs and says why.
//
// Protocol (dynamic distribution: cases differ in cost by orders of magnitude): every
// rank other than 0 sends rank 0 a request carrying its last result (or nothing), and
// gets back the next case index, or -1 to stop. Rank 0 hands out indices from the same
// counter as its own worker thread, which runs cases too, and collects every result.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace cmp::mpi {

/// Size and rank of an mpirun launch read from the environment (Open MPI, MPICH, Slurm);
/// size 1 when not launched by mpirun.
int launched_size();
int launched_rank();
/// True when this program was built with MPI.
bool built();

/// Runs `n` cases over the ranks; `run(i)` returns case i's result as text. On rank 0
/// returns true with results[i] for every case; on the other ranks returns false when
/// the work is done. Call only when built() and launched_size() > 1. Once MPI has
/// started, rank 0 runs cases on a thread named "ringvib-cases", and the other ranks
/// defer SIGINT, SIGTERM and SIGHUP by 2 s, so that rank 0 (which owns the run's files)
/// always dies first and cleans up; sweep_mpi.cpp says what mpirun does with signals.
bool distribute(int argc, char** argv, int n, const std::function<std::string(int)>& run,
                std::vector<std::string>& results);

/// `ringvib sweep --ranks N ...`: runs `mpirun -np N <this program> <argv without --ranks>`
/// and returns the exit code a serial run would have: mpirun's own, but 128 + signal when
/// SIGINT, SIGTERM or SIGHUP reached this launcher and the sweep did not finish. Such a
/// signal is passed to the ranks, not to mpirun (which runs in a process group of its own,
/// with no terminal input): Open MPI's mpirun, signalled itself, exits 1 whatever the
/// ranks did (sweep_mpi.cpp). ring::InputError (exit 2) when no mpirun is on PATH.
int launch(int ranks, int argc, char** argv);

}  // namespace cmp::mpi
