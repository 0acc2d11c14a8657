// writeValidationImages: the pictures of a validated frame (frame_validation.h), for a person.
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "shadowvol/error.h"
#include "shadowvol/image_io.h"
#include "shadowvol/mesh_io.h"
#include "shadowvol/validate/frame_validation.h"

namespace shadowvol {
namespace {

// What the overlay marks at a pixel; later kinds win where several apply.
enum Mark : std::uint8_t { kNone, kLeak, kFalseShadow, kZfailZpass, kStencilCount, kMarkKinds };
constexpr std::array<std::array<std::uint8_t, 3>, kMarkKinds> kMarkColour = {
    {{0, 0, 0}, {255, 0, 0}, {255, 220, 0}, {0, 220, 255}, {255, 0, 255}}};
constexpr const char* kMarkName[kMarkKinds] = {"", "light leak: exact shadow, method lit",
                                               "false shadow: exact lit, method shadowed",
                                               "z-fail count != z-pass count", "stencil != crossing count"};

std::vector<std::uint8_t> marks(const FrameValidation& v, const RenderedFrame& frame) {
  const std::size_t n = std::size_t(v.width) * std::size_t(v.height);
  std::vector<std::uint8_t> m(n, kNone);
  for (std::size_t k = 0; k < n; ++k) {
    const bool methodShadowed = !frame.shadowed.empty() ? frame.shadowed[k] != 0 : (frame.hybrid && frame.stencil[k] != 0);
    if (v.exact[k] == PixelClass::Shadowed && !methodShadowed) m[k] = kLeak;
    if (v.exact[k] == PixelClass::Lit && methodShadowed) m[k] = kFalseShadow;
    if (v.counts && v.exact[k] != PixelClass::Background) {
      if (v.zfailVsZpass && v.counts->zfail[k] != v.counts->zpass[k]) m[k] = kZfailZpass;
      bool admissible = false;
      for (int c = v.counts->zfailMin[k]; c <= v.counts->zfailMax[k]; ++c) admissible |= std::uint8_t(c) == frame.stencil[k];
      if (!admissible) m[k] = kStencilCount;
    }
  }
  return m;
}

std::array<std::uint8_t, 3> exactColour(PixelClass c) {
  switch (c) {
    case PixelClass::FacingAway: return {40, 60, 120};  // dark blue
    case PixelClass::OutsideLight: return {50, 50, 50};  // dark grey
    case PixelClass::Lit: return {235, 235, 235};        // white
    case PixelClass::Shadowed: return {110, 110, 110};   // grey
    default: return {0, 0, 0};                           // background
  }
}

// The frame in grey, each marked pixel in its colour, and a ring of 2 pixels around it in the
// colour at half strength, so that a single wrong pixel is still seen in a whole frame.
std::vector<std::uint8_t> overlayImage(const FrameValidation& v, const RenderedFrame& frame,
                                       const std::vector<std::uint8_t>& m) {
  const int w = v.width, h = v.height;
  std::vector<std::uint8_t> out(std::size_t(w) * std::size_t(h) * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t k = std::size_t(y) * std::size_t(w) + std::size_t(x);
      std::uint8_t g = exactColour(v.exact[k])[0];
      if (!frame.rgba.empty())
        g = std::uint8_t((int(frame.rgba[4 * k]) * 3 + int(frame.rgba[4 * k + 1]) * 6 + int(frame.rgba[4 * k + 2])) / 10);
      std::array<std::uint8_t, 3> px = {g, g, g};
      if (m[k] != kNone) {
        px = kMarkColour[m[k]];
      } else {
        std::uint8_t near = kNone;
        for (int dy = -2; dy <= 2; ++dy)
          for (int dx = -2; dx <= 2; ++dx) {
            const int xx = x + dx, yy = y + dy;
            if (xx < 0 || yy < 0 || xx >= w || yy >= h || std::abs(dx) + std::abs(dy) > 3) continue;
            near = std::max(near, m[std::size_t(yy) * std::size_t(w) + std::size_t(xx)]);
          }
        if (near != kNone)
          for (int c = 0; c < 3; ++c) px[c] = std::uint8_t((int(kMarkColour[near][c]) + int(g)) / 2);
      }
      std::copy(px.begin(), px.end(), &out[3 * k]);
    }
  return out;
}

// overlay.svg: overlay.png with a legend beside it (colour, meaning, pixel count).
void writeOverlayLegend(const std::filesystem::path& dir, const FrameValidation& v, const std::vector<std::uint8_t>& m) {
  std::array<std::size_t, kMarkKinds> count{};
  for (auto k : m) ++count[k];
  const int legendW = 330, rowH = 22;
  writeAtomically(dir / "overlay.svg", [&](const std::filesystem::path& tmp) {
    std::ofstream svg(tmp);
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << v.width + legendW << "\" height=\""
        << std::max(v.height, rowH * 6) << "\" font-family=\"sans-serif\" font-size=\"13\">\n"
        << "<image href=\"overlay.png\" x=\"0\" y=\"0\" width=\"" << v.width << "\" height=\"" << v.height << "\"/>\n"
        << "<text x=\"" << v.width + 10 << "\" y=\"18\">marked pixels (ringed 2 px for visibility)</text>\n";
    for (int k = kLeak; k < kMarkKinds; ++k) {
      const int y = rowH * k;
      const auto& c = kMarkColour[k];
      svg << "<rect x=\"" << v.width + 10 << "\" y=\"" << y + 6 << "\" width=\"14\" height=\"14\" fill=\"rgb(" << int(c[0])
          << "," << int(c[1]) << "," << int(c[2]) << ")\"/>\n"
          << "<text x=\"" << v.width + 30 << "\" y=\"" << y + 18 << "\">" << kMarkName[k] << ": " << count[k] << "</text>\n";
    }
    svg << "</svg>\n";
    svg.close();  // the check below must see the last write
    if (!svg) throw InputError((dir / "overlay.svg").string(), "", "", "writing the legend failed (disk full?)");
  });
}

}  // namespace

void writeValidationImages(const std::filesystem::path& dir, const FrameValidation& v, const RenderedFrame& frame) {
  const std::size_t n = std::size_t(v.width) * std::size_t(v.height);
  std::vector<std::uint8_t> exact(n * 3);
  for (std::size_t k = 0; k < n; ++k) {
    const auto c = exactColour(v.exact[k]);
    std::copy(c.begin(), c.end(), &exact[3 * k]);
  }
  writePng(dir / "exact.png", v.width, v.height, 3, exact);
  const std::vector<std::uint8_t> m = marks(v, frame);
  writePng(dir / "overlay.png", v.width, v.height, 3, overlayImage(v, frame, m));
  writeOverlayLegend(dir, v, m);
  if (!frame.rgba.empty()) writePng(dir / "frame.png", v.width, v.height, 4, frame.rgba);
  if (!frame.hybrid) return;
  writePng(dir / "stencil.png", v.width, v.height, 3, stencilPicture(frame.stencil));
  std::vector<int> zfail(n, 0);
  if (v.counts) std::copy(v.counts->zfail.begin(), v.counts->zfail.end(), zfail.begin());
  writePng(dir / "count.png", v.width, v.height, 3, countPicture(zfail));
}

}  // namespace shadowvol
