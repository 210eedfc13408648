#pragma once
// `--memory-limit SIZE`, on every command that reads scenes or images: the most bytes the command
// may ask for (scenes/memory_limit.hpp says what is counted). Without it, LUXEL_MEMORY_LIMIT's
// size, else the default (4 GiB). A size that does not parse is one line and exit 2; a request
// beyond the limit is one line naming the file and what it needs, exit 1.

#include "luxel/scenes/memory_limit.hpp"

#include <CLI/CLI.hpp>

#include <cstdint>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>

namespace luxel::cli {

struct MemoryLimitOption {
  std::string size;  ///< as given; empty: not given

  void add_to(CLI::App& cmd) {
    cmd.add_option("--memory-limit", size,
                   "Refuse work needing more memory than SIZE (bytes, or 512M, 8G...; default: $LUXEL_MEMORY_LIMIT, else 4G)")
        ->check([](const std::string& text) -> std::string {
          try {
            scenes::parse_memory_size(text);
            return "";
          } catch (const std::invalid_argument& e) {
            return e.what();
          }
        });
  }

  /// The limit in bytes, or nullopt after one line on stderr for a bad LUXEL_MEMORY_LIMIT (`code` 2).
  std::optional<uint64_t> bytes(const std::string& command, int& code) const {
    try {
      return size.empty() ? scenes::memory_limit_from_environment() : scenes::parse_memory_size(size);
    } catch (const std::invalid_argument& e) {
      std::cerr << "luxel " << command << ": " << e.what() << "\n";
      code = 2;
      return std::nullopt;
    }
  }
};

}  // namespace luxel::cli
