// See decimal_numbers.hpp.
#include "decimal_numbers.hpp"

#include <string>

namespace zraster::cli {
namespace {

CLI::Validator decimal() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            const std::size_t sign = !text.empty() && (text[0] == '+' || text[0] == '-') ? 1 : 0;
            std::size_t zeros = sign;
            while (zeros + 1 < text.size() && text[zeros] == '0') ++zeros;
            if (zeros > sign && text.find_first_of("xXbBoO", zeros) == zeros)
                return "expected a whole number in decimal, got '" + text + "'";
            text.erase(sign, zeros - sign);
            // ("1e3", "1.0", "5 ": CLI11's own range check would call them out of range.)
            if (text.size() == sign ||
                text.find_first_not_of("0123456789", sign) != std::string::npos)
                return "expected a whole number, got '" + text + "'";
            return {};
        },
        "", "decimal");
}

CLI::Validator decimal_number() {
    return CLI::Validator(
        [](std::string& text) -> std::string {
            if (text.find_first_of(" \t\r\nxXpP") != std::string::npos)
                return "expected a decimal number, got '" + text + "'";
            return {};
        },
        "", "decimal number");
}

}  // namespace

void read_numbers_in_decimal(CLI::App& app) {
    for (CLI::Option* option : app.get_options()) {
        // ("UINT:POSITIVE": the type, then what a check added to it.)
        const std::string type = option->get_type_name();
        const std::string base = type.substr(0, type.find(':'));
        if (base == "INT" || base == "UINT") option->transform(decimal());
        if (base == "FLOAT") option->transform(decimal_number());
    }
    for (CLI::App* sub : app.get_subcommands({})) read_numbers_in_decimal(*sub);
}

}  // namespace zraster::cli
