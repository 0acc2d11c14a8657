// CPU-built volumes drawn (VolumeSource::Explicit) and the frame's images read back.
#include "renderer_impl.h"

namespace shadowvol::gl {

void Renderer::Impl::uploadVolume(const VolumeMesh& volume) {
  const TriangleMesh m = volume.toTriangleMesh();
  SV_GL(glBindBuffer(GL_ARRAY_BUFFER, volumeVbo.id()));
  SV_GL(glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(m.positions.size() * sizeof(glm::vec3)), m.positions.data(),
                     GL_STREAM_DRAW));
  SV_GL(glBindBuffer(GL_ARRAY_BUFFER, 0));
  SV_GL(glBindVertexArray(volumeVao.id()));
  SV_GL(glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(m.triangles.size() * sizeof(m.triangles[0])),
                     m.triangles.data(), GL_STREAM_DRAW));
  SV_GL(glBindVertexArray(0));
}

void Renderer::Impl::drawExplicitVolume(const CameraSetup& cam, std::size_t triangles, RenderResult& result) {
  volumeProgram.use();
  volumeProgram.set("worldToClip", toFloat(cam.proj * cam.view));
  SV_GL(glBindVertexArray(volumeVao.id()));
  SV_GL(glDrawElements(GL_TRIANGLES, GLsizei(triangles * 3), GL_UNSIGNED_INT, nullptr));
  SV_GL(glBindVertexArray(0));
  result.volumeTriangles = triangles;
}

void Renderer::Impl::flipRows(std::vector<std::uint8_t>& image, std::size_t rowBytes, int rows) {
  for (int y = 0; y < rows / 2; ++y)
    std::swap_ranges(image.begin() + std::ptrdiff_t(std::size_t(y) * rowBytes),
                     image.begin() + std::ptrdiff_t(std::size_t(y + 1) * rowBytes),
                     image.begin() + std::ptrdiff_t(std::size_t(rows - 1 - y) * rowBytes));
}

void Renderer::Impl::readColour(const CameraSetup& cam, RenderResult& r) {
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, cameraFbo.id()));
  r.rgba.resize(std::size_t(cam.w) * std::size_t(cam.h) * 4);
  SV_GL(glReadBuffer(GL_COLOR_ATTACHMENT0));
  SV_GL(glReadPixels(0, 0, cam.w, cam.h, GL_RGBA, GL_UNSIGNED_BYTE, r.rgba.data()));
  flipRows(r.rgba, std::size_t(cam.w) * 4, cam.h);
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, 0));
}

void Renderer::Impl::readShadowImages(const CameraSetup& cam, bool stencil, VisibilitySource visibility,
                                      RenderResult& r) {
  const int w = cam.w, h = cam.h;
  r.width = w;
  r.height = h;
  // Rows of one-byte pixels are read tight into w x h buffers: the renderer sets a pack alignment
  // of 1 once (renderer.cpp) and no pass may change it (one that set 4 made these reads overflow
  // at widths not a multiple of 4: a fourteenth probe's heap corruption).
  GLint alignment = 0;
  SV_GL(glGetIntegerv(GL_PACK_ALIGNMENT, &alignment));
  SV_CHECK_EQ(alignment, 1);
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, cameraFbo.id()));
  const std::size_t pixels = std::size_t(w) * std::size_t(h);
  if (stencil || visibility == VisibilitySource::FromStencil) {
    std::vector<std::uint8_t> counts(pixels);
    SV_GL(glReadPixels(0, 0, w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, counts.data()));
    flipRows(counts, std::size_t(w), h);
    if (visibility == VisibilitySource::FromStencil) {
      r.visibility.resize(pixels);
      for (std::size_t k = 0; k < pixels; ++k) r.visibility[k] = counts[k] == 0 ? 255 : 0;
    }
    if (stencil) r.stencil = std::move(counts);
  }
  if (visibility == VisibilitySource::FromAttachment) {
    r.visibility.resize(pixels);
    SV_GL(glReadBuffer(GL_COLOR_ATTACHMENT1));
    SV_GL(glReadPixels(0, 0, w, h, GL_RED, GL_UNSIGNED_BYTE, r.visibility.data()));
    SV_GL(glReadBuffer(GL_COLOR_ATTACHMENT0));
    flipRows(r.visibility, std::size_t(w), h);
  } else if (visibility == VisibilitySource::AllLit) {
    r.visibility.assign(pixels, 255);
  }
  SV_GL(glBindFramebuffer(GL_FRAMEBUFFER, 0));
}

}  // namespace shadowvol::gl
