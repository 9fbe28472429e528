#include "settings/SettingLimits.h"

#include <algorithm>
#include <cstdio>

#include "common/Error.h"
#include "settings/ValueParse.h"

namespace mixengine {
namespace {

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

/// " (computed from the settings given: a, b, c)" unless `key` itself was given.
std::string origin(const std::string& key, const std::vector<std::string>& given) {
    if (given.empty() || std::find(given.begin(), given.end(), key) != given.end())
        return {};
    std::string text = " (computed from the settings given: ";
    for (std::size_t i = 0; i < given.size() && i < 4; ++i)
        text += (i ? ", " : "") + given[i];
    return text + (given.size() > 4 ? ", ...)" : ")");
}

bool endsWith(const std::string& text, std::string_view suffix) {
    return text.size() >= suffix.size() &&
           text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

void checkLineWidths(const Settings& settings, const std::vector<std::string>& given) {
    const std::string factor_key(key::initial_layer_line_width_factor.name);
    const double factor = settings.ratio(key::initial_layer_line_width_factor);
    for (const auto& [key, text] : settings.all()) {  // every *line_width, Cura's and any a profile adds
        if (!endsWith(key, "line_width"))
            continue;
        const double width = parseReal(key, text);
        if (width < kMinLineWidthMm) {
            throw InputError("setting '" + key + "': " + number(width) + " mm is narrower than the " +
                             number(kMinLineWidthMm) + " mm a line can be printed" + origin(key, given));
        }
        if (width * factor < kMinLineWidthMm) {
            throw InputError("setting '" + factor_key + "': " + number(factor * 100) + " % of " + key + " " +
                             number(width) + " mm makes first-layer lines narrower than " +
                             number(kMinLineWidthMm) + " mm" + origin(factor_key, given));
        }
    }
}

}  // namespace mixengine
