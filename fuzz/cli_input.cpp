#include "fuzz_support.hpp"
#include "inputs.hpp"

#include "command_line.hpp"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace luxel::fuzz {

namespace {

/// Redirects std::cout and std::cerr into strings for its lifetime.
class CapturedOutput {
 public:
  CapturedOutput() : out_(std::cout.rdbuf(out_text_.rdbuf())), err_(std::cerr.rdbuf(err_text_.rdbuf())) {}
  ~CapturedOutput() {
    std::cout.rdbuf(out_);
    std::cerr.rdbuf(err_);
  }
  std::string out() const { return out_text_.str(); }
  std::string err() const { return err_text_.str(); }

 private:
  std::ostringstream out_text_, err_text_;
  std::streambuf* out_;
  std::streambuf* err_;
};

std::string quoted(const std::vector<std::string>& args) {
  std::string line;
  for (const std::string& a : args) line += (line.empty() ? "'" : " '") + a + "'";
  return line;
}

}  // namespace

void read_cli_input(std::span<const uint8_t> input) {
  std::vector<std::string> args = {"luxel"};
  std::string current;
  for (const uint8_t byte : input) {
    if (byte == '\n') {
      if (args.size() == kMaxCliArguments) break;
      args.push_back(current);
      current.clear();
    } else {
      current += char(byte);
    }
  }
  if (args.size() < kMaxCliArguments && !current.empty()) args.push_back(current);
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());

  std::optional<int> code;
  std::string out, err;
  {
    CapturedOutput captured;
    try {
      cli::CommandLine command_line;
      code = command_line.parse(static_cast<int>(argv.size()), argv.data());
    } catch (const std::exception& e) {
      err = captured.err();
      finding("luxel " + quoted(args) + ": parsing threw " + e.what());
    }
    out = captured.out();
    err = captured.err();
  }
  if (!code) {
    if (!err.empty()) finding("luxel " + quoted(args) + ": accepted, with '" + err + "' on stderr");
    return;
  }
  if (*code == 0) {
    if (out.empty() || !err.empty()) finding("luxel " + quoted(args) + ": exit 0 without help on stdout alone");
    return;
  }
  if (*code != 2) finding("luxel " + quoted(args) + ": exit code " + std::to_string(*code) + ", not 2");
  // One line, "luxel: ..." or "luxel SUBCOMMAND: ...". An argument holding a newline is not in
  // the input's alphabet (newlines separate arguments), so every '\n' is the parser's.
  if (err.rfind("luxel", 0) != 0 || err.empty() || err.back() != '\n' || err.find('\n') != err.size() - 1)
    finding("luxel " + quoted(args) + ": refused without one line on stderr: '" + err + "'");
}

void write_cli_seeds(const std::string& dir) {
  // The command lines of the README and the CLI tests, one argument per line.
  const std::vector<std::vector<std::string>> lines = {
      {"--help"},
      {"render", "--scene", "builtin:demo", "--width", "1280", "--height", "720", "--msaa", "4", "--out", "out/demo.png"},
      {"render", "--scene", "builtin:tris", "--threads", "2", "--stats", "--out", "out/tris.png"},
      {"render", "--scene", "builtin:courtyard", "--camera", "1", "--model", "ps_2_0", "--bake", "quick", "--frames",
       "0:9", "--fps", "24", "--out", "f%04d.png"},
      {"render", "--scene", "builtin:courtyard", "--sequence", "30", "--exposure", "1.5", "--tonemap-algorithm",
       "percentile", "--histogram", "31", "--query-latency", "3", "--no-bloom", "--film-grain", "7", "--look",
       "archival", "--out", "seq"},
      {"compare", "--scene", "builtin:courtyard", "--models", "ps_2_0,ps_3_0", "--frames", "3", "--out", "cmp"},
      {"cost", "--shader", "VertexLitGeneric", "--pixels", "4096", "--scene", "builtin:courtyard"},
      {"export", "--scene", "builtin:courtyard", "--out", "courtyard.glb"},
      {"info", "--scene", "model.glb", "--camera", "0"},
      {"bake", "--scene", "builtin:courtyard", "--quick"},
      {"grade", "in.png", "out.png", "--lut", "builtin:day-for-night", "--lut", "a.cube", "--weight", "0.25",
       "--weight", "0.5", "--exact"},
      {"report", "speed-error", "--probes", "probes", "--scene", "builtin:courtyard", "--width", "64", "--out", "r"},
  };
  int n = 0;
  for (const std::vector<std::string>& line : lines) {
    std::ofstream out(std::filesystem::path(dir) / ("command-" + std::to_string(n++)), std::ios::binary);
    for (size_t i = 0; i < line.size(); ++i) out << (i ? "\n" : "") << line[i];
  }
}

}  // namespace luxel::fuzz
