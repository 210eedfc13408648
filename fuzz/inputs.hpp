#pragma once
// One input of each fuzz target, read the way luxel reads that kind of file, and judged. The
// fuzzers (fuzz/*_fuzz.cpp) apply these to every input they make; the regression tests
// (tests/fuzz) apply the same to every input kept in tests/data/fuzz/TARGET. A defect calls
// finding(); what is not a defect is an input read, or refused with the reader's documented error
// of one line naming the file.

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>

namespace luxel::fuzz {

/// A defect an input showed.
struct Finding : std::logic_error {
  using std::logic_error::logic_error;
};

/// Reports a defect: prints it and aborts (what a fuzzer needs), or throws Finding after
/// throw_findings() (what a test needs).
[[noreturn]] void finding(const std::string& what);
void throw_findings();

/// glTF import (.gltf and .glb, told apart by their first bytes as load_gltf does). A scene that
/// loads must export as .glb and load again.
void read_gltf_input(std::span<const uint8_t> input);

/// read_image on bytes in memory (a glTF buffer view's way; OpenImageIO picks the format by the
/// contents). An image read must be within kMaxImageSide, its pixels matching its size.
void read_image_input(std::span<const uint8_t> input);

/// A LUT file as a scene or `luxel grade` names it (postfx::color_transform_named): the first
/// byte picks the extension (kLutExtensions), the rest is the file. A LUT read is sampled on the
/// engine's lattice, and its transform applied to NaN, infinite and huge colors must return.
void read_lut_input(std::span<const uint8_t> input);
inline constexpr const char* kLutExtensions[] = {"cube", "3dl", "csp", "spi1d", "spi3d", "spimtx",
                                                 "clf", "ctf", "cc", "ccc", "cdl", "raw"};

/// A bake index (bake.json) beside the maps of a cheap bake of builtin:demo made once per process,
/// the token @HASH@ standing for the scene's input hash (a fuzzer could not guess it) and
/// @VERSION@ for the bake format's version (kept inputs stay readable when it changes). A bake that
/// loads must attach to the scene and leave it valid (scenes::validate).
void read_bake_input(std::span<const uint8_t> input);

/// `luxel`'s arguments (cli/command_line.hpp), one per line (at most kMaxCliArguments; no
/// argument can hold a newline), parsed but not run: accepted, or --help on stdout with exit 0,
/// or one line on stderr with exit 2. Parsing must not throw.
void read_cli_input(std::span<const uint8_t> input);
inline constexpr size_t kMaxCliArguments = 64;

/// Seeds of the formats luxel writes itself, written to `dir`: small images in every format
/// OpenImageIO writes here; the engine's identity LUT as .cube and .raw (extension byte first);
/// the demo bake's index with its hash replaced by @HASH@.
void write_image_seeds(const std::string& dir);
void write_lut_seeds(const std::string& dir);
void write_bake_seed(const std::string& dir);
/// The command lines of the README and the CLI tests, one argument per line.
void write_cli_seeds(const std::string& dir);

}  // namespace luxel::fuzz
