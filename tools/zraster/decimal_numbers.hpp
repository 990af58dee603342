// Numeric options read as decimal text only. CLI11 converts integers with strtoll(text, 0), which
// takes "010" as octal 8 and "0x10" as 16 (`--views 010` rendered 8 views without a word), calls
// "1e3" out of range and "1 " not convertible; and reads floats with strtod, which takes hex
// ("0x1p5") and a trailing space says "Could not convert: --fovy = 60".
#pragma once
#include <CLI/CLI.hpp>

namespace zraster::cli {

// Every numeric option of `app` and its subcommands, checked last: whole numbers are decimal
// digits (leading zeros dropped: "010" is 10; a base prefix, an exponent, a point or a space
// refused naming the option); numbers are decimal (no hex, no spaces).
void read_numbers_in_decimal(CLI::App& app);

}  // namespace zraster::cli
