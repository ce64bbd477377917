// An orderer that is another program (README "Judging your own sorter"): prepare() writes
// the scene once (cells .vtu, triangles .off, voxels .vti) and starts CMD through /bin/sh
// with VOBENCH_SCENE (that file) and VOBENCH_KIND (cells | triangles | voxels) in its
// environment; order() writes one JSON line {"view_index": i, "camera": {...}} on CMD's
// stdin and reads one line {"order": [...], "phases": {"name": seconds}} from its stdout.
// The round trip is the frame's time: the sorter's own phases are recorded as
// "sorter:NAME" and the rest of the round trip as "round_trip" (they sum to the round trip).
// A sorter that crashes, hangs past the timeout, answers malformed JSON or a permutation
// that is not complete is an InputError naming the command and the view (exit 2): a broken
// sorter is not a wrong one.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "harness/bench/orderer.h"

namespace vob {

constexpr double kDefaultSorterTimeout = 60.0;  // seconds per answer (first: includes start-up)

std::unique_ptr<Orderer> make_external_orderer(const std::string& command, double timeout_seconds);

// The view index sent with the next order() calls (the Orderer API passes only a camera);
// a no-op for any other orderer.
void set_external_view_index(Orderer& orderer, int view_index);

// After the last view (`check`): the sorter's stdin is closed and it must exit with status
// 0 within the timeout; InputError naming the command otherwise (whatever it left running
// is killed either way). A no-op for any other orderer.
void finish_external_orderer(Orderer& orderer);

// Registers `name` as an orderer of `kind` scenes running `command` (suite entries
// {"name": ..., "command": ...}). Registering the same name with the same command, kind and
// timeout again is a no-op (a suite read twice); a name taken otherwise is an InputError.
void register_external_orderer(const std::string& name, const std::string& command, SceneKind kind,
                               double timeout_seconds);

// Why `order` is not a complete back-to-front permutation of the scene's primitives
// (voxels: of its significant voxels), e.g. "has 99 ids for 100 cells"; empty when it is.
std::string permutation_problem(const Scene& scene, const std::vector<int32_t>& order);

}  // namespace vob
