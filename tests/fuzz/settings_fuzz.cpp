// libFuzzer target: the setting value parsers (settings/ValueParse.h) and the typed reading of
// setting text (settings/TypedText.h). The first input byte picks the parser, the rest is the text.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "common/Error.h"
#include "settings/TypedText.h"
#include "settings/ValueParse.h"

namespace {

constexpr std::string_view kTypes[] = {"float", "int",     "extruder", "optional_extruder",
                                       "bool",  "polygon", "polygons", "[int]",
                                       "str",   "enum",    "unknown"};
constexpr std::size_t kTypeCount = sizeof(kTypes) / sizeof(kTypes[0]);

void parseWith(std::uint8_t selector, std::string_view text) {
    using namespace mixengine;
    const std::string_view key = "fuzzed_setting";
    switch (selector % 10) {
        case 0:
            (void)parseBool(key, text);
            break;
        case 1:
            (void)parseReal(key, text);
            break;
        case 2:
            (void)parseInteger(key, text);
            break;
        case 3:
            (void)parseLengthMicrons(key, text);
            break;
        case 4:
            (void)parseRatio(key, text);
            break;
        case 5:
            (void)parseRealList(key, text);
            break;
        case 6:
            (void)parsePolygonMicrons(key, text);
            break;
        case 7:
            (void)parsePolygonsMicrons(key, text);
            break;
        case 8:
            (void)parseMatrix3(key, text);
            break;
        default: {
            const formula::Value value = valueFromText(key, kTypes[(selector / 10) % kTypeCount], text);
            (void)textFromValue(value);
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0)
        return 0;
    const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
    try {
        parseWith(data[0], text);
    } catch (const mixengine::InputError&) {
    }
    return 0;
}
