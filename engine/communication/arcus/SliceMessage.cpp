#include "communication/arcus/SliceMessage.h"

#include <bit>
#include <cmath>
#include <cstring>

#include "Cura.pb.h"
#include "common/Error.h"

namespace mixengine {
namespace {

constexpr std::size_t kBytesPerTriangle = 9 * sizeof(float);

template <typename Repeated>
SettingValues valuesOf(const Repeated& settings) {
    SettingValues values;
    for (const cura::proto::Setting& setting : settings)
        values[setting.name()] = setting.value();
    return values;
}

float littleEndianFloat(const char* bytes) {
    std::uint32_t word = 0;
    std::memcpy(&word, bytes, sizeof word);
    if constexpr (std::endian::native == std::endian::big)
        word = __builtin_bswap32(word);
    return std::bit_cast<float>(word);
}

int extruderOf(const SettingValues& object_settings, const std::string& name) {
    const auto it = object_settings.find("extruder_nr");
    if (it == object_settings.end())
        return 0;
    try {
        return std::stoi(it->second);
    } catch (const std::exception&) {
        throw InputError("Slice message: object '" + name + "': extruder_nr '" + it->second +
                         "' is not an extruder number");
    }
}

MeshInput meshOf(const cura::proto::Object& object) {
    MeshInput mesh;
    mesh.name = object.name().empty() ? "object " + std::to_string(object.id()) : object.name();
    mesh.settings = valuesOf(object.settings());
    mesh.default_extruder = extruderOf(mesh.settings, mesh.name);
    mesh.soups.push_back(soupFromVertexBytes(object.vertices(), mesh.name));
    return mesh;
}

}  // namespace

TriangleSoup soupFromVertexBytes(const std::string& bytes, const std::string& object_name) {
    if (bytes.size() % kBytesPerTriangle != 0)
        throw InputError("Slice message: object '" + object_name + "' has " + std::to_string(bytes.size()) +
                         " vertex bytes, not a whole number of triangles (36 bytes each)");
    TriangleSoup soup;
    soup.name = object_name;
    soup.triangles.resize(bytes.size() / kBytesPerTriangle);
    const char* p = bytes.data();
    for (auto& triangle : soup.triangles) {
        for (Vec3& corner : triangle) {
            const float x = littleEndianFloat(p), y = littleEndianFloat(p + 4), z = littleEndianFloat(p + 8);
            if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
                throw InputError("Slice message: object '" + object_name +
                                 "' has a vertex that is not finite");
            corner = {x, y, z};
            p += 12;
        }
    }
    return soup;
}

SliceRequest requestFromSlice(const cura::proto::Slice& slice) {
    SliceRequest request;
    request.settings_from_frontend = true;
    request.user.global = valuesOf(slice.global_settings().settings());
    for (const cura::proto::Extruder& extruder : slice.extruders()) {
        if (extruder.id() < 0 || extruder.id() > 63)
            throw InputError("Slice message: extruder id " + std::to_string(extruder.id()) +
                             " is out of range");
        request.user.extruders[extruder.id()] = valuesOf(extruder.settings().settings());
    }
    for (const cura::proto::SettingExtruder& limit : slice.limit_to_extruder()) {
        const auto train = request.user.extruders.find(limit.extruder());
        if (train == request.user.extruders.end())
            continue;  // a missing train: keep the global value
        const auto value = train->second.find(limit.name());
        if (value != train->second.end())
            request.user.global[limit.name()] = value->second;
    }
    for (const cura::proto::ObjectList& list : slice.object_lists()) {
        MeshGroupInput group;
        group.settings = valuesOf(list.settings());
        for (const cura::proto::Object& object : list.objects())
            group.meshes.push_back(meshOf(object));
        request.groups.push_back(std::move(group));
    }
    return request;
}

}  // namespace mixengine
