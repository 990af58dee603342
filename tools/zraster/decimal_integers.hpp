// Whole-number options read in decimal. CLI11 converts integers with strtoll(text, 0), which
// takes "010" as octal 8 and "0x10" as 16: `--views 010` rendered 8 views without a word.
#pragma once
#include <CLI/CLI.hpp>

namespace zraster::cli {

// Every integer option of `app` and its subcommands, added last: leading zeros are dropped
// ("010" is 10) and a base prefix ("0x10", "0b1", "0o7") is refused naming the option.
void read_integers_in_decimal(CLI::App& app);

}  // namespace zraster::cli
