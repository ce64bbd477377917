// The farm's messages (harness/mpi): JSON text between rank 0 and the workers. A worker says
// it is free (kReady), rank 0 answers with a group (kAssign) or kStop; records and context
// lines go to rank 0 as kRecord, failed jobs as kFailure. Waiting polls with a 1 ms sleep
// rather than MPI's busy wait, so a waiting rank leaves its core to the measuring ones.
#pragma once
#include <optional>
#include <string>

namespace vob::farm {

enum Tag : int { kReady = 1, kAssign = 2, kStop = 3, kRecord = 4, kFailure = 5 };

struct Message {
  int source = -1, tag = 0;
  std::string text;
};

void send(int dest, Tag tag, const std::string& text);
std::optional<Message> poll(int source);  // a message waiting from `source` (-1: any), or none
Message wait(int source);                 // the next message from `source`, sleeping meanwhile
void nap();                               // 1 ms

}  // namespace vob::farm
