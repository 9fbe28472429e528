#include "settings/JsonText.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>

namespace mixengine {

std::string pythonFloatText(double value) {
    if (std::isnan(value))
        return "nan";
    if (std::isinf(value))
        return value > 0 ? "inf" : "-inf";
    // Shortest round-trip digits in scientific form, then laid out the way Python's repr does:
    // fixed notation for decimal exponents -4 <= e < 16, scientific otherwise.
    char buffer[64];
    auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific);
    std::string sci(buffer, end);
    const bool negative = sci[0] == '-';
    if (negative)
        sci.erase(0, 1);
    const auto e_pos = sci.find('e');
    const int exponent = std::stoi(sci.substr(e_pos + 1));
    std::string digits = sci.substr(0, e_pos);
    digits.erase(std::remove(digits.begin(), digits.end(), '.'), digits.end());
    std::string text;
    if (exponent >= -4 && exponent < 16) {
        if (exponent < 0) {
            text = "0." + std::string(static_cast<std::size_t>(-exponent - 1), '0') + digits;
        } else if (static_cast<std::size_t>(exponent) + 1 >= digits.size()) {
            text = digits + std::string(static_cast<std::size_t>(exponent) + 1 - digits.size(), '0') + ".0";
        } else {
            text = digits.substr(0, exponent + 1) + "." + digits.substr(exponent + 1);
        }
    } else {
        text = digits.substr(0, 1);
        if (digits.size() > 1)
            text += "." + digits.substr(1);
        char exp_text[16];
        std::snprintf(exp_text, sizeof exp_text, "e%c%02d", exponent < 0 ? '-' : '+', std::abs(exponent));
        text += exp_text;
    }
    return negative ? "-" + text : text;
}

std::string jsonToPythonText(const nlohmann::json& value) {
    switch (value.type()) {
        case nlohmann::json::value_t::boolean:
            return value.get<bool>() ? "True" : "False";
        case nlohmann::json::value_t::number_integer:
            return std::to_string(value.get<long long>());
        case nlohmann::json::value_t::number_unsigned:
            return std::to_string(value.get<unsigned long long>());
        case nlohmann::json::value_t::number_float:
            return pythonFloatText(value.get<double>());
        case nlohmann::json::value_t::string:
            return value.get<std::string>();
        case nlohmann::json::value_t::null:
            return "None";
        case nlohmann::json::value_t::array: {
            std::string text = "[";
            for (std::size_t i = 0; i < value.size(); ++i) {
                if (i)
                    text += ", ";
                const auto& item = value[i];
                text += item.is_string() ? "'" + item.get<std::string>() + "'" : jsonToPythonText(item);
            }
            return text + "]";
        }
        default:
            return value.dump();
    }
}

}  // namespace mixengine
