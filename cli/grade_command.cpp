// luxel grade IN OUT --lut LUT [--lut LUT ...] [--weight W ...] [--exact] [--save-lut FILE] [--threads N]:
// color-corrects an 8-bit image with up to four LUTs (postfx/color_correction.hpp). A LUT is a
// file OpenColorIO reads (.cube, .3dl, .csp, .spi3d, .clf...), a Source .raw, or builtin:NAME (a
// grade preset). --save-lut writes the engine's 32^3 lattice of the one LUT as .cube or .raw.
//
// The engine's way (the default): each LUT sampled on the 32^3 lattice with 8-bit entries,
// blended by colorcorrection_ps2x drawn through the rasterizer, 8 bits out. --exact: the same
// blend in float, each LUT applied at its own resolution and interpolation (a file through
// OpenColorIO, a preset exactly), to measure what the engine's way loses; written as floats
// where OUT's format holds them (.exr), else rounded to 8 bits.
//
// Weights: one per LUT, each in [0, 1], summing to at most 1 (beyond 1 the blend no longer mixes
// but brightens); the frame keeps 1 - sum (luxel's rule; the SDK's is closed,
// docs/fidelity.md#color-correction). Without --weight, the LUTs share the frame equally (1/n each).
//
// Exit codes: 2 for bad arguments (weights, counts, an unknown builtin:NAME), 1 for files that
// cannot be read or written; one line on stderr each.

#include "commands.hpp"
#include "memory_limit_option.hpp"

#include "luxel/postfx/color_correction.hpp"
#include "luxel/postfx/lut_file.hpp"
#include "luxel/postfx/lut_source.hpp"
#include "luxel/postfx/raw_lut_file.hpp"
#include "luxel/rasterizer/limits.hpp"
#include "luxel/scenes/image_io.hpp"
#include "luxel/scenes/load.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace luxel::cli {

namespace {

struct GradeOptions {
  std::string in, out;
  std::vector<std::string> luts;
  std::vector<float> weights;
  bool exact = false;
  std::string save_lut;
  int threads = 0;
  MemoryLimitOption memory;
};

std::string number(float v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

/// The weights the LUTs get, or an error message for bad ones.
std::vector<float> weights_of(const GradeOptions& o, std::string& error) {
  if (o.weights.empty()) return std::vector<float>(o.luts.size(), 1.0f / float(o.luts.size()));
  if (o.weights.size() != o.luts.size()) {
    error = std::to_string(o.weights.size()) + " --weight for " + std::to_string(o.luts.size()) +
            " --lut: give one per LUT, or none";
    return {};
  }
  float sum = 0.0f;
  for (float w : o.weights) {
    if (!(w >= 0.0f && w <= 1.0f)) {
      error = "--weight " + number(w) + ": must be in [0, 1]";
      return {};
    }
    sum += w;
  }
  if (sum > 1.0f + 1e-6f) {
    error = "--weight: the weights sum to " + number(sum) + "; at most 1 (the frame keeps 1 - sum)";
    return {};
  }
  return o.weights;
}

/// The input as an 8-bit frame, refused when it and its grade (in float with --exact) would need
/// more than `memory_limit`; throws std::runtime_error "IN: problem".
rasterizer::Image read_frame(const std::string& path, bool exact, uint64_t memory_limit) {
  scenes::PixelImage image = scenes::read_image(path, memory_limit);
  const uint64_t w = uint64_t(image.width), h = uint64_t(image.height);
  scenes::check_memory(path, 2 * scenes::image_bytes(w, h, false) + (exact ? scenes::image_bytes(w, h, true) : 0),
                       "a " + std::to_string(w) + "x" + std::to_string(h) + " image graded" + (exact ? " in float" : ""),
                       memory_limit);
  if (image.is_hdr()) {
    throw std::runtime_error(path + ": a float image; luxel grade takes 8-bit frames (the engine grades its 8-bit back buffer)");
  }
  rasterizer::Image frame(image.width, image.height);
  frame.rgba = std::move(image.rgba8);
  return frame;
}

/// "t1.cube (3D LUT 17^3, trilinear) x 0.5, builtin:warm (grade: color balance) x 0.5"
std::string describe(const std::vector<postfx::ColorTransform>& transforms, const std::vector<float>& weights) {
  std::string what;
  for (size_t k = 0; k < transforms.size(); ++k) {
    what += (k ? ", " : "") + transforms[k].name + " (" + transforms[k].description + ") x " + number(weights[k]);
  }
  return what;
}

void grade_exact(const GradeOptions& o, const rasterizer::Image& frame,
                 const std::vector<postfx::ColorTransform>& transforms, const std::vector<float>& weights) {
  std::vector<postfx::WeightedTransform> weighted;
  for (size_t k = 0; k < transforms.size(); ++k) weighted.push_back({&transforms[k], weights[k]});
  scenes::PixelImage image;
  image.width = frame.width, image.height = frame.height;
  image.rgba32f = postfx::color_correct_exact(frame, weighted);
  scenes::write_image(image, o.out);
  std::printf("%s -> %s: %s, exact (float, each LUT at its own resolution)\n", o.in.c_str(), o.out.c_str(),
              describe(transforms, weights).c_str());
}

void grade_engine(const GradeOptions& o, const rasterizer::Image& frame,
                  const std::vector<postfx::ColorTransform>& transforms, const std::vector<float>& weights) {
  if (frame.width > rasterizer::kMaxTargetSize || frame.height > rasterizer::kMaxTargetSize) {
    throw std::runtime_error(o.in + ": " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                             " is larger than the rasterizer's targets (" + std::to_string(rasterizer::kMaxTargetSize) +
                             " on a side); --exact has no such limit");
  }
  std::vector<postfx::Lut> luts;
  for (const postfx::ColorTransform& t : transforms) luts.push_back(postfx::sample_lut(t));
  std::vector<postfx::WeightedLut> weighted;
  for (size_t k = 0; k < luts.size(); ++k) weighted.push_back({&luts[k], weights[k]});
  rasterizer::Context ctx(o.threads);
  const rasterizer::Image graded = postfx::color_correct(ctx, frame, weighted);
  scenes::write_image(graded.width, graded.height, graded.rgba, o.out);
  std::printf("%s -> %s: %s, the engine's way (32^3 LUTs, 8 bits in and out)\n", o.in.c_str(), o.out.c_str(),
              describe(transforms, weights).c_str());
}

void save_lut(const postfx::Lut& lut, const std::string& path, const std::string& name) {
  if (scenes::has_extension(path, ".raw")) postfx::write_raw_lut(lut, path);
  else postfx::write_cube(lut, path, name);
}

int run_grade(const GradeOptions& o) {
  int code = 0;
  const std::optional<uint64_t> memory_limit = o.memory.bytes("grade", code);
  if (!memory_limit) return code;
  std::string error;
  const std::vector<float> weights = weights_of(o, error);
  if (o.luts.size() > size_t(postfx::kMaxLuts)) {
    error = std::to_string(o.luts.size()) + " --lut: the engine blends at most " + std::to_string(postfx::kMaxLuts);
  } else if (!o.save_lut.empty() && o.luts.size() != 1) {
    error = "--save-lut writes one LUT; " + std::to_string(o.luts.size()) + " --lut given";
  } else if (!o.save_lut.empty() && !scenes::has_extension(o.save_lut, ".cube") && !scenes::has_extension(o.save_lut, ".raw")) {
    error = "--save-lut " + o.save_lut + ": the name must end in .cube or .raw";
  }
  if (!error.empty()) {
    std::cerr << "luxel grade: " << error << "\n";
    return 2;
  }
  try {
    std::vector<postfx::ColorTransform> transforms;
    for (const std::string& name : o.luts) transforms.push_back(postfx::color_transform_named(name));
    const rasterizer::Image frame = read_frame(o.in, o.exact, *memory_limit);
    if (o.exact) grade_exact(o, frame, transforms, weights);
    else grade_engine(o, frame, transforms, weights);
    if (!o.save_lut.empty()) save_lut(postfx::sample_lut(transforms[0]), o.save_lut, transforms[0].name);
  } catch (const std::invalid_argument& e) {  // an unknown builtin:NAME
    std::cerr << "luxel grade: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {  // files: "PATH: problem"
    std::cerr << "luxel grade: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

Runner add_grade_command(CLI::App& app) {
  auto o = std::make_shared<GradeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "grade", "Color-correct an 8-bit image with up to four LUTs, the way Source's engine does (or exactly, --exact)");
  cmd->add_option("in", o->in, "Input image (8-bit: PNG, JPEG, TGA, TIFF...)")->required();
  cmd->add_option("out", o->out, "Output image; its extension picks the format")->required();
  cmd->add_option("--lut", o->luts,
                  "A LUT file OpenColorIO reads (.cube, .3dl, .csp, .spi3d, .clf...), a Source .raw, or builtin:NAME "
                  "(day-for-night, archival, warm, cool); up to 4")
      ->required()
      ->allow_extra_args(false);  // one value per --lut: what follows stays IN and OUT
  cmd->add_option("--weight", o->weights,
                  "One weight in [0, 1] per --lut, in order, summing to at most 1; the image keeps 1 - sum "
                  "(default: 1/n each)")
      ->allow_extra_args(false);
  cmd->add_flag("--exact", o->exact,
                "Blend in float with each LUT at its own resolution and interpolation (OpenColorIO for files), "
                "instead of the engine's 32^3 8-bit volumes");
  cmd->add_option("--save-lut", o->save_lut,
                  "Also write the (one) LUT's 32^3 engine lattice: FILE.cube, or FILE.raw (Source's own format)");
  cmd->add_option("--threads", o->threads, "Worker threads (default: all cores); never changes the result")
      ->check(CLI::Range(0, 256));
  o->memory.add_to(*cmd);
  return [cmd, o]() -> int {
    if (!cmd->parsed()) return -1;
    return run_grade(*o);
  };
}

}  // namespace luxel::cli
