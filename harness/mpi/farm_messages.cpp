#include "harness/mpi/farm_messages.h"

#include <mpi.h>

#include <chrono>
#include <thread>

namespace vob::farm {

void send(int dest, Tag tag, const std::string& text) {
  MPI_Send(text.data(), int(text.size()), MPI_CHAR, dest, tag, MPI_COMM_WORLD);
}

std::optional<Message> poll(int source) {
  int flag = 0;
  MPI_Status st;
  MPI_Iprobe(source < 0 ? MPI_ANY_SOURCE : source, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st);
  if (!flag) return std::nullopt;
  int count = 0;
  MPI_Get_count(&st, MPI_CHAR, &count);
  Message m;
  m.source = st.MPI_SOURCE;
  m.tag = st.MPI_TAG;
  m.text.resize(size_t(count));
  MPI_Recv(m.text.data(), count, MPI_CHAR, st.MPI_SOURCE, st.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return m;
}

Message wait(int source) {
  for (;;) {
    if (auto m = poll(source)) return *m;
    nap();
  }
}

void nap() { std::this_thread::sleep_for(std::chrono::milliseconds(1)); }

}  // namespace vob::farm
