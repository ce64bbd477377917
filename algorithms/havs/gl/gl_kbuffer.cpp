#include "algorithms/havs/gl/gl_kbuffer.h"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "algorithms/havs/gl/gl_kbuffer_impl.h"
#include "harness/gl/view_projection.h"
#include "harness/raster/sample_frame.h"

namespace vob::havs {

GlKBuffer::GlKBuffer(const FaceData& fd) {
  try {
    impl_ = std::make_unique<Impl>(fd);
  } catch (const GlUnavailable&) {
    throw;
  } catch (const std::exception& e) {
    throw GlUnavailable(e.what());
  }
}

GlKBuffer::~GlKBuffer() = default;

std::string GlKBuffer::version() const { return impl_->ctx.version(); }
std::string GlKBuffer::renderer() const { return impl_->ctx.renderer(); }

size_t GlKBuffer::bytes() const {
  const Impl& d = *impl_;
  const size_t px = size_t(d.tex_w) * d.tex_h;
  return d.static_bytes + d.ibo_bytes + px * (16 * size_t(d.tex_k) + 16 + 4) +
         (d.face_first.capacity() + d.face_indices.capacity() + d.frame_indices.capacity()) * 4;
}

GlFrameStats GlKBuffer::render(const Camera& view, const std::vector<int32_t>& face_order, int k,
                               GlDrawMode mode, Image& image, std::vector<uint32_t>* pixel_fragments) {
  if (k < 1 || k > kMaxK) throw std::invalid_argument("GL k-buffer: k out of range");
  Impl& d = *impl_;
  d.ctx.make_current();
  const SampleFrame frame(view, 1);
  const int w = frame.cols(), h = frame.rows();
  const Impl::Programs& prog = d.programs_for(k);
  d.ensure_targets(w, h, k);

  // Per-view data: the camera as a double matrix (no depth: clip z = 0, nothing clipped
  // but w <= 0), and the sample frame's ray terms.
  const Vec3 eye = frame.eye(), fw = frame.forward();
  const std::array<double, 16> mvp = gl::view_projection(view);
  std::vector<double> fb;
  fb.reserve(size_t(8 + 4 * (w + h)));
  fb.insert(fb.end(), {eye.x, eye.y, eye.z, view.ortho ? 1.0 : 0.0, fw.x, fw.y, fw.z, d.fd->tau0});
  for (int y = 0; y < h; ++y) {
    const Vec3 t = frame.row_term(y);
    fb.insert(fb.end(), {t.x, t.y, t.z, 0.0});
  }
  for (int x = 0; x < w; ++x) {
    const Vec3 t = frame.col_term(x);
    fb.insert(fb.end(), {t.x, t.y, t.z, 0.0});
  }
  d.gl.glNamedBufferData(d.frame_ssbo, GLsizeiptr(fb.size() * 8), fb.data(), GL_STREAM_DRAW);

  // The faces' triangles in drawing order; in serialized mode, runs of faces whose pixel
  // rectangles (conservative: projected vertices, one pixel of margin) do not overlap.
  d.frame_indices.clear();
  std::vector<std::pair<size_t, size_t>> runs;  // [first index, end index)
  std::vector<int32_t> stamp;
  if (mode == GlDrawMode::Serialized) stamp.assign(size_t(w) * h, -1);
  int32_t run = 0;
  size_t run_start = 0;
  for (const int32_t f : face_order) {
    if (mode == GlDrawMode::Serialized) {
      const int n = d.fd->faces->face_size(f);
      const int32_t* id = d.fd->faces->face_points(f);
      double lx = 1e300, hx = -1e300, ly = 1e300, hy = -1e300;
      bool all_front = true;
      for (int j = 0; j < n && all_front; ++j) {
        double x, y, zc;
        if (!frame.project(d.fd->scene.mesh().points[id[j]], x, y, zc)) {
          all_front = false;
          break;
        }
        lx = std::min(lx, x), hx = std::max(hx, x), ly = std::min(ly, y), hy = std::max(hy, y);
      }
      SampleRect rect = all_front ? SampleRect{floor_to_int(lx - 0.5) - 1, floor_to_int(ly - 0.5) - 1,
                                               ceil_to_int(hx - 0.5) + 1, ceil_to_int(hy - 0.5) + 1}
                                  : frame.bounds();
      rect = rect.intersect(frame.bounds());
      if (!rect.empty()) {
        bool overlap = false;
        for (int y = rect.y0; y <= rect.y1 && !overlap; ++y)
          for (int x = rect.x0; x <= rect.x1; ++x)
            if (stamp[size_t(y) * w + x] == run) {
              overlap = true;
              break;
            }
        if (overlap) {
          runs.emplace_back(run_start, d.frame_indices.size());
          run_start = d.frame_indices.size();
          ++run;
        }
        for (int y = rect.y0; y <= rect.y1; ++y)
          std::fill_n(stamp.begin() + size_t(y) * w + rect.x0, rect.x1 - rect.x0 + 1, run);
      }
    }
    d.frame_indices.insert(d.frame_indices.end(), d.face_indices.begin() + d.face_first[f],
                           d.face_indices.begin() + d.face_first[f + 1]);
  }
  runs.emplace_back(run_start, d.frame_indices.size());
  d.ibo_bytes = std::max(d.ibo_bytes, d.frame_indices.size() * 4);
  d.gl.glNamedBufferData(d.ibo, GLsizeiptr(d.frame_indices.size() * 4), d.frame_indices.data(), GL_STREAM_DRAW);

  // Clear the state (no entries, outside, no fragments) and the colour.
  const uint32_t zero_u[4] = {0, 0, 0, 0};
  const float zero_f[4] = {0, 0, 0, 0};
  d.gl.glClearTexImage(d.tex_state, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, zero_u);
  d.gl.glClearTexImage(d.tex_accum, 0, GL_RGBA, GL_FLOAT, zero_f);
  d.gl.glBindImageTexture(0, d.tex_entries, 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32UI);
  d.gl.glBindImageTexture(1, d.tex_accum, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  d.gl.glBindImageTexture(2, d.tex_state, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
  d.gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, d.face_ssbo);
  d.gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, d.quad_ssbo);
  d.gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, d.frame_ssbo);
  d.gl.glBindFramebuffer(GL_FRAMEBUFFER, d.fbo);
  d.gl.glViewport(0, 0, w, h);
  d.gl.glProgramUniformMatrix4dv(prog.draw, prog.mvp, 1, GL_FALSE, mvp.data());
  d.gl.glProgramUniform1i(prog.draw, prog.nrows, h);
  d.gl.glUseProgram(prog.draw);
  d.gl.glBindVertexArray(d.vao);
  GlFrameStats st;
  for (const auto& [b, e] : runs) {
    if (e == b) continue;
    d.gl.glDrawElements(GL_TRIANGLES, GLsizei(e - b), GL_UNSIGNED_INT,
                     reinterpret_cast<const void*>(b * sizeof(uint32_t)));
    ++st.draws;
    if (mode == GlDrawMode::Serialized) d.gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  st.triangles = int64_t(d.frame_indices.size() / 3);
  d.gl.glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  d.gl.glUseProgram(prog.flush);
  d.gl.glDrawArrays(GL_TRIANGLES, 0, 3);
  d.gl.glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);

  std::vector<float> rgba(size_t(w) * h * 4);
  d.gl.glGetTextureImage(d.tex_accum, 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * 4), rgba.data());
  std::vector<uint32_t> state(size_t(w) * h);
  d.gl.glGetTextureImage(d.tex_state, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, GLsizei(state.size() * 4), state.data());
  d.gl.glFinish();
  d.gl.check("render");
  d.gl.glBindFramebuffer(GL_FRAMEBUFFER, 0);
  image.width = w;
  image.height = h;
  image.rgb.resize(size_t(3) * w * h);
  for (size_t p = 0; p < size_t(w) * h; ++p) {
    for (int c = 0; c < 3; ++c) image.rgb[3 * p + c] = rgba[4 * p + c];
    st.fragments += state[p] >> 16;
  }
  if (pixel_fragments) {
    pixel_fragments->resize(state.size());
    for (size_t p = 0; p < state.size(); ++p) (*pixel_fragments)[p] = state[p] >> 16;
  }
  return st;
}

}  // namespace vob::havs
