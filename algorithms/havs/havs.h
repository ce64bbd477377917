// Plugin `havs`: Callahan et al.'s hardware-assisted visibility sorting, in software.
// Faces sorted by centroid distance with the LSD radix sort ("cpu sort"), then rasterized in
// that order into a per-pixel k-buffer that finishes the sort and composites ray segments
// ("k-buffer"); see kbuffer.h and havs_frame.h for where we follow the paper and where we
// interpret it.
// Parameters k, analyze, backend, gl_draw: declared (defaults, ranges, one-line docs) in
// havs_orderer_info(); what they do beyond that line:
//   analyze  the measurement runs untimed, once per view (the result is deterministic, so
//            repeats of the same view reuse it), and always reruns the software k-buffer
//   backend  the "k-buffer" phase: software (kbuffer.h on the CPU, parallel over bands of
//            rows) or gl (the same k-buffer as an OpenGL 4.5 fragment shader with image
//            load/store on OSMesa/llvmpipe, gl/gl_kbuffer.h; the cpu sort and the face order
//            are the same). With gl, prepare() creates the GL context and fails with one
//            InputError line when it cannot.
//   gl_draw  batched draws all faces in one call (the paper's way; the read-modify-write may
//            race, Fig. 5); serialized draws runs of faces with disjoint pixel rectangles
//            separated by glMemoryBarrier (race free)
// Ordering::order is a complete back-to-front permutation of cells derived from the face
// sort (each cell at the position of its last-arriving face, havs_frame.h), for the
// harness' completeness check; the oracle's count on it is only the "derived cell order"
// (records' oracle_cell_order). HAVS composites itself (Claims::composites): its verdict,
// the records' `oracle` and `vobench check`'s, is composited_verdict() (havs.cpp: the
// analysis below, untimed, S = 1 only; backend=gl gets the software k-buffer's verdict on
// the same face order). With analyze, the same analysis also fills Ordering::counters:
//   havs_fragments, havs_max_list (Table 2 "Max A"), havs_max_k_needed (Table 2 "Max k"),
//   havs_pixels_k_gt_2, havs_pixels_k_gt_6, havs_covered_pixels, havs_violating_pixels
//   (pixels whose composited segment sequence differs from the exact one),
//   havs_violating_segments, havs_image_rmse / havs_image_max_error / havs_pixels_off (the
//   k-buffer image against exact-order compositing of the same segments).
//   backend=gl adds havs_gl_fragments (fragments the shader saw) and havs_gl_draws.
// Claims: heuristic in general; exact at a view where k >= havs_max_k_needed.
#pragma once
#include "harness/bench/registry.h"

namespace vob {
OrdererInfo havs_orderer_info();
}
