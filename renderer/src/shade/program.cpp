#include "shade/program.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include "base/lanes.h"
#include "framebuffer/pixel.h"
#include "shader/ir.h"

namespace raster::detail {
namespace {

using shader::kBlockLanes;

// A program's float as GL writes it to a byte: clamped to 0..1 (NaN 0), times 255, rounded to nearest even
// (adding and taking away 1.5 * 2^23 rounds a float below 2^22 that way, in every lane width alike).
void to_bytes(const float* in, float* out) {
  for (int i = 0; i < kBlockLanes; i += kLanes) {
    FloatLanes v;
    std::memcpy(&v, in + i, sizeof v);
    v = v > 0.0f ? v : FloatLanes{};  // NaN too
    v = v < 1.0f ? v : FloatLanes{} + 1.0f;
    v = (v * 255.0f + 12582912.0f) - 12582912.0f;
    std::memcpy(out + i, &v, sizeof v);
  }
}

// Image pixel of lane l of the block at (bx, by).
int lane_x(int bx, int l) {
  return bx + (l & 7);
}
int lane_y(int by, int l) {
  return by + (l >> 3);
}

// gl_FragCoord for the block at (bx, by) at sample position `at` (1/256 px from the pixel's corner):
// measured from the rectangle's bottom-left corner, y up, as GL's window coordinates are.
void frag_coord(const ShaderPlan& p, const shader::Program& program, shader::Registers& registers, int bx,
                int by, SamplePoint at) {
  if (program.frag_coord == shader::kUnusedSlot) return;
  std::uint32_t* x = registers.slot(program.frag_coord);
  const float top = static_cast<float>(p.rect_y + p.rect_height);
  for (int l = 0; l < kBlockLanes; ++l) {
    x[l] = std::bit_cast<std::uint32_t>(static_cast<float>(lane_x(bx, l) - p.rect_x) + at.x / 256.0f);
    x[kBlockLanes + l] =
        std::bit_cast<std::uint32_t>(top - (static_cast<float>(lane_y(by, l)) + at.y / 256.0f));
    x[2 * kBlockLanes + l] = std::bit_cast<std::uint32_t>(0.5f);  // a full-screen pass's depth
    x[3 * kBlockLanes + l] = std::bit_cast<std::uint32_t>(1.0f);
  }
}

template <int C>
void write_block(const Surface& surface, int bx, int by, std::uint64_t bits,
                 const float (&rgba)[4][kBlockLanes], bool opaque) {
  for (std::uint64_t m = bits; m; m &= m - 1) {
    const int l = std::countr_zero(m);
    const Rgba8 c{static_cast<std::uint8_t>(rgba[0][l]), static_cast<std::uint8_t>(rgba[1][l]),
                  static_cast<std::uint8_t>(rgba[2][l]),
                  opaque ? std::uint8_t{255} : static_cast<std::uint8_t>(rgba[3][l])};
    put<C>(surface.pixel<C>(lane_x(bx, l), lane_y(by, l)), c, !opaque);
  }
  if (surface.sample_count > 1) surface.one_colour<C>(bx, by, bits);
}

// The pixel of lane l as floats 0..255 (a discarded sample keeps what is there).
void existing(const Surface& surface, int bx, int by, int l, float (&out)[4]) {
  const std::uint8_t* px = surface.pixel(lane_x(bx, l), lane_y(by, l));
  const int n = surface.channels;
  const std::uint8_t rgba[4] = {px[0], px[n >= 3 ? 1 : 0], px[n >= 3 ? 2 : 0],
                                n == 2 || n == 4 ? px[n - 1] : std::uint8_t{255}};
  for (int k = 0; k < 4; ++k) out[k] = rgba[k];
}

// The block's colours over its samples: each sample's output in bytes as floats, averaged. False (with
// `fault` or the meter stopped) when the render must stop.
bool shade_block(const ShaderPlan& p, shader::Registers& registers, const shader::RunContext& context,
                 const Surface& surface, int bx, int by, std::uint64_t bits, float (&rgba)[4][kBlockLanes],
                 std::uint64_t& kept, ProgramFault& fault, int index) {
  const shader::Program& program = p.shader->program();
  const SamplePoint centre;
  const std::vector<SamplePoint>* pattern = p.samples > 1 ? &sample_pattern(p.samples) : nullptr;
  kept = 0;
  for (int s = 0; s < p.samples; ++s) {
    frag_coord(p, program, registers, bx, by, pattern ? (*pattern)[static_cast<std::size_t>(s)] : centre);
    const shader::RunResult r = shader::run_block(program, registers, context);
    if (r.status == shader::RunResult::Status::stopped) return false;
    if (r.status == shader::RunResult::Status::iterations) {
      fault = {index, r.loop, lane_x(bx, r.lane), lane_y(by, r.lane)};
      return false;
    }
    const std::uint32_t* discarded = registers.slot(shader::kDiscardSlot);
    float sample[4][kBlockLanes];
    for (int k = 0; k < 4; ++k) {
      const bool given = k < program.output_slots;
      const float* v =
          given
              ? reinterpret_cast<const float*>(registers.slot(program.output + static_cast<shader::Slot>(k)))
              : nullptr;
      if (given)
        to_bytes(v, sample[k]);
      else
        std::fill(std::begin(sample[k]), std::end(sample[k]), k == 3 ? 255.0f : 0.0f);
    }
    for (int l = 0; l < kBlockLanes; ++l) {
      float px[4] = {sample[0][l], sample[1][l], sample[2][l], sample[3][l]};
      if (discarded[l]) {
        if (p.samples == 1 || !(bits >> l & 1)) continue;
        existing(surface, bx, by, l, px);
      } else {
        kept |= std::uint64_t{1} << l;
      }
      for (int k = 0; k < 4; ++k) rgba[k][l] = s == 0 ? px[k] : rgba[k][l] + px[k];
    }
  }
  if (p.samples > 1) {
    const float share = 1.0f / static_cast<float>(p.samples);
    for (auto& channel : rgba)
      for (float& v : channel) v = ((v * share) + 12582912.0f) - 12582912.0f;
    kept = bits;
  }
  return true;
}

}  // namespace

Programs prepare_programs(const Scene& scene, const RenderPlan& plan, StopMeter& meter) {
  Programs programs;
  programs.lanes = plan.scalar_shading       ? shader::Lanes::scalar
                   : plan.simd == Simd::avx2 ? shader::Lanes::avx2
                                             : shader::Lanes::sse2;
  programs.ready.resize(plan.shaders.size());
  std::size_t next = 0;
  for (const DrawPlan& draw : plan.draws) {
    if (draw.shader < 0) continue;
    Programs::Ready& r = programs.ready[next++];
    r.plan = &plan.shaders[static_cast<std::size_t>(draw.shader)];
    const ShaderPrimitive& s = scene.shaders[scene.primitives[draw.primitive].mesh];
    for (int c = 0; c < 4; ++c) {
      const std::int32_t t = r.plan->channels[static_cast<std::size_t>(c)];
      if (t < 0) continue;
      const MipChain& chain =
          r.mips.emplace_back(build_raw_mips(s.textures[static_cast<std::size_t>(t)], &meter));
      if (meter.stopped()) return programs;
      r.channels[c].levels = chain.levels;
    }
  }
  return programs;
}

std::int64_t Programs::bytes() const {
  std::int64_t n = 0;
  for (const Ready& r : ready)
    for (const MipChain& chain : r.mips)
      for (std::size_t l = 1; l < chain.levels.size(); ++l)
        n += std::int64_t{chain.levels[l].width} * chain.levels[l].height * 4;
  return n;
}

shader::Registers& ProgramThread::registers(const Programs& programs, int index) {
  if (files_.size() <= static_cast<std::size_t>(index)) files_.resize(static_cast<std::size_t>(index) + 1);
  std::unique_ptr<shader::Registers>& file = files_[static_cast<std::size_t>(index)];
  if (file) return *file;
  const ShaderPlan& p = *programs.ready[static_cast<std::size_t>(index)].plan;
  const shader::Program& program = p.shader->program();
  file = std::make_unique<shader::Registers>(program.slots);
  for (const auto& [slot, bits] : p.uniforms) std::fill_n(file->slot(slot), kBlockLanes, bits);
  shader::prepare(program, *file, programs.lanes);
  return *file;
}

std::int64_t ProgramThread::bytes() const {
  std::int64_t n = 0;
  for (const auto& f : files_)
    if (f) n += static_cast<std::int64_t>(f->bytes());
  return n;
}

bool draw_program(const Programs& programs, int index, ProgramThread& thread, const Surface& surface,
                  Rect clip, const BlockMasks* edges, StopMeter& meter, ProgramFault& fault) {
  const Programs::Ready& ready = programs.ready[static_cast<std::size_t>(index)];
  const ShaderPlan& p = *ready.plan;
  const Rect r{std::max(clip.x0, p.x0), std::max(clip.y0, p.y0), std::min(clip.x1, p.x1),
               std::min(clip.y1, p.y1)};
  if (r.x0 >= r.x1 || r.y0 >= r.y1) return true;
  shader::Registers& registers = thread.registers(programs, index);
  shader::RunContext context;
  for (int c = 0; c < 4; ++c)
    context.channels[c] = ready.channels[c].levels.empty() ? nullptr : &ready.channels[c];
  context.max_iterations = p.max_iterations;
  context.meter = &meter;
  context.lanes = programs.lanes;
  float rgba[4][kBlockLanes];
  for (int by = r.y0 & ~7; by < r.y1; by += 8)
    for (int bx = r.x0 & ~7; bx < r.x1; bx += 8) {
      std::uint64_t bits = 0;  // the block's pixels inside `r`
      for (int l = 0; l < kBlockLanes; ++l) {
        const int x = lane_x(bx, l), y = lane_y(by, l);
        if (x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1) bits |= std::uint64_t{1} << l;
      }
      if (edges) bits &= edges->at(bx, by);
      if (!bits) continue;
      if (meter.add(kBlockLanes * p.samples)) return false;
      std::uint64_t kept = 0;
      if (!shade_block(p, registers, context, surface, bx, by, bits, rgba, kept, fault, index)) return false;
      bits &= kept;
      switch (surface.channels) {
        case 1:
          write_block<1>(surface, bx, by, bits, rgba, p.opaque);
          break;
        case 2:
          write_block<2>(surface, bx, by, bits, rgba, p.opaque);
          break;
        case 3:
          write_block<3>(surface, bx, by, bits, rgba, p.opaque);
          break;
        default:
          write_block<4>(surface, bx, by, bits, rgba, p.opaque);
          break;
      }
    }
  return true;
}

}  // namespace raster::detail
