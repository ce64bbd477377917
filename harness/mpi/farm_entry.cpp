// vobench_mpi_farm (harness/bench/farm.h): MPI_Init, where this rank is (host, ranks on it,
// its core with --pin), then rank 0 coordinates and the others work; MPI_Finalize.
#include <mpi.h>
#include <sched.h>

#include <cstdio>
#include <thread>

#include "harness/bench/runner.h"
#include "harness/mpi/farm.h"

namespace {

// The record's placement fields. ranks_on_host counts the workers on this host: rank 0 only
// hands out groups and sleeps between messages, so it is not counted.
nlohmann::json placement(int rank, int ranks, bool pin) {
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &node);
  const int worker = rank != 0 ? 1 : 0;
  int workers_here = 0, before_me = 0, node_rank = 0;
  MPI_Allreduce(&worker, &workers_here, 1, MPI_INT, MPI_SUM, node);
  MPI_Exscan(&worker, &before_me, 1, MPI_INT, MPI_SUM, node);
  MPI_Comm_rank(node, &node_rank);
  if (node_rank == 0) before_me = 0;  // MPI_Exscan leaves the first rank's result undefined
  MPI_Comm_free(&node);
  nlohmann::json p = vob::lone_placement();
  p["rank"] = rank;
  p["ranks"] = ranks;
  p["ranks_on_host"] = workers_here;
  if (pin) {
    // Workers on cores 0, 1, ...; rank 0 on the core after them.
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    const int core = (worker ? before_me : workers_here) % cores;
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(core, &set);
    if (sched_setaffinity(0, sizeof set, &set) == 0) p["core"] = core;
    else std::fprintf(stderr, "vobench: note: rank %d: cannot pin to core %d; not pinned\n", rank, core);
  }
  return p;
}

}  // namespace

extern "C" int vobench_mpi_farm(const vob::FarmRequest* req) {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (ranks < 2) {
    std::fprintf(stderr, "vobench: %s: --mpi: 1 rank: the farm needs rank 0 and at least one worker "
                 "(mpirun -np 3 vobench ...)\n", req->name.c_str());
    MPI_Finalize();
    return 2;
  }
  const nlohmann::json where = placement(rank, ranks, req->pin);
  int status = 0;
  try {
    if (rank == 0)
      status = vob::farm::coordinate(*req, ranks, where);
    else
      vob::farm::work(*req, where);
  } catch (const std::exception& e) {
    // Not a job's failure (those are recorded): the results file or the farm itself.
    std::fprintf(stderr, "vobench: %s: rank %d: %s\n", req->name.c_str(), rank, e.what());
    MPI_Abort(MPI_COMM_WORLD, 2);
  }
  MPI_Finalize();
  return status;
}
