#include "mesh/formats/ThreeMfReader.h"

#include <cmath>
#include <cstring>
#include <system_error>

#include "mesh/Mesh.h"
#include "mesh/formats/Affine3.h"
#include "mesh/formats/Lib3mfHandle.h"
#include "mesh/formats/MessageText.h"
#include "mesh/formats/ThreeMfPaint.h"

namespace mixengine {

namespace {

constexpr int kMaxComponentDepth = 32;

/// Millimetres per model unit (3MF `unit` attribute).
double millimetresPerUnit(DWORD unit) {
    switch (unit) {
        case NMR::MODELUNIT_MICROMETER:
            return 0.001;
        case NMR::MODELUNIT_CENTIMETER:
            return 10.0;
        case NMR::MODELUNIT_INCH:
            return 25.4;
        case NMR::MODELUNIT_FOOT:
            return 304.8;
        case NMR::MODELUNIT_METER:
            return 1000.0;
        default:
            return 1.0;
    }
}

Affine3 toAffine(const NMR::MODELTRANSFORM& t) {
    Affine3 a;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 4; ++j) {
            a.m[i][j] = t.m_fFields[i][j];
        }
    }
    return a;
}

class ThreeMfLoader {
  public:
    ThreeMfLoader(std::string label, std::string stem) : call_(std::move(label)), stem_(std::move(stem)) {}

    std::vector<TriangleSoup> load(const std::filesystem::path& file, std::vector<std::string>& warnings);

  private:
    Affine3 open(const std::filesystem::path& file, std::vector<std::string>& warnings);
    TriangleSoup readBuildItem(NMR::PLib3MFBase* item, std::size_t item_number, const Affine3& to_mm);
    void appendObject(NMR::PLib3MFBase* object, const Affine3& to_mm, int depth, TriangleSoup& soup);
    void appendComponents(NMR::PLib3MFBase* object, const Affine3& to_mm, int depth, TriangleSoup& soup);
    void appendMesh(NMR::PLib3MFBase* mesh, const Affine3& to_mm, TriangleSoup& soup);
    std::vector<std::uint32_t> meshColors(NMR::PLib3MFBase* mesh, DWORD triangle_count);
    std::uint32_t triangleColor(NMR::PLib3MFBase* handler, DWORD triangle);
    std::string objectName(NMR::PLib3MFBase* object, std::size_t item_number) const;
    [[noreturn]] void fail(const std::string& defect) const {
        throw InputError(call_.label() + ": " + defect);
    }

    Lib3mfCaller call_;
    std::string stem_;  ///< names objects that have no name: "<stem>_<build item number>"
    Lib3mfHandle model_;
    std::vector<NMR::MODELMESHVERTEX> vertices_;         ///< reused between mesh objects
    std::vector<NMR::MODELMESHTRIANGLE> triangles_;      ///< reused between mesh objects
    std::map<std::uint32_t, std::vector<int>> painted_;  ///< painted facets by object id (ThreeMfPaint.h)
};

std::uint32_t ThreeMfLoader::triangleColor(NMR::PLib3MFBase* handler, DWORD triangle) {
    NMR::eModelPropertyType type = NMR::MODELPROPERTYTYPE_NONE;
    if (NMR::lib3mf_propertyhandler_getpropertytype(handler, triangle, &type) != 0)
        return 0;
    if (type == NMR::MODELPROPERTYTYPE_COLOR) {
        NMR::MODELMESH_TRIANGLECOLOR_SRGB color{};
        if (NMR::lib3mf_propertyhandler_getcolor(handler, triangle, &color) != 0)
            return 0;
        const NMR::MODELMESHCOLOR_SRGB& c = color.m_Colors[0];  // a facet's colour: its first corner's
        return Mesh::kPaintedRgb | (std::uint32_t{c.m_Red} << 16) | (std::uint32_t{c.m_Green} << 8) |
               c.m_Blue;
    }
    if (type != NMR::MODELPROPERTYTYPE_BASEMATERIALS)
        return 0;
    DWORD group = 0;
    DWORD index = 0;
    if (NMR::lib3mf_propertyhandler_getbasematerial(handler, triangle, &group, &index) != 0 || group == 0)
        return 0;
    Lib3mfHandle materials;
    BYTE r = 0, g = 0, b = 0, a = 0;
    if (NMR::lib3mf_model_getbasematerialbyid(model_.get(), group, materials.out()) != 0 ||
        NMR::lib3mf_basematerial_getdisplaycolor(materials.get(), index, &r, &g, &b, &a) != 0)
        return 0;
    return Mesh::kPaintedRgb | (std::uint32_t{r} << 16) | (std::uint32_t{g} << 8) | b;
}

/// The painted colour of each triangle: its colour or base material property, else the extruder
/// painted on it in PrusaSlicer/OrcaSlicer (Mesh::kPaintedExtruder | n); empty when none is painted.
std::vector<std::uint32_t> ThreeMfLoader::meshColors(NMR::PLib3MFBase* mesh, DWORD triangle_count) {
    std::vector<std::uint32_t> colors(triangle_count, 0);
    bool any = false;
    Lib3mfHandle handler;
    if (NMR::lib3mf_meshobject_createpropertyhandler(mesh, handler.out()) == 0) {
        for (DWORD t = 0; t < triangle_count; ++t) {
            colors[t] = triangleColor(handler.get(), t);
            any = any || colors[t] != 0;
        }
    }
    DWORD id = 0;
    const auto painted =
        NMR::lib3mf_resource_getresourceid(mesh, &id) == 0 ? painted_.find(id) : painted_.end();
    if (!any && painted != painted_.end() && painted->second.size() == triangle_count) {
        for (DWORD t = 0; t < triangle_count; ++t) {
            const int extruder = painted->second[t];
            colors[t] = extruder > 0 ? Mesh::kPaintedExtruder | static_cast<std::uint32_t>(extruder) : 0;
            any = any || colors[t] != 0;
        }
    }
    if (!any)
        colors.clear();
    return colors;
}

Affine3 ThreeMfLoader::open(const std::filesystem::path& file, std::vector<std::string>& warnings) {
    call_.check(NMR::lib3mf_createmodel(model_.out()), nullptr, "creating a model");
    Lib3mfHandle reader;
    call_.check(NMR::lib3mf_model_queryreader(model_.get(), "3mf", reader.out()), model_.get(),
                "creating a reader");
    const std::string path = file.string();
    call_.check(NMR::lib3mf_reader_readfromfileutf8(reader.get(), path.c_str()), reader.get(), "");
    DWORD count = 0;
    call_.check(NMR::lib3mf_reader_getwarningcount(reader.get(), &count), reader.get(), "reading warnings");
    for (DWORD i = 0; i < count; ++i) {
        DWORD code = 0;
        ULONG needed = 0;
        std::string text(1024, '\0');
        if (NMR::lib3mf_reader_getwarningutf8(reader.get(), i, &code, text.data(),
                                              static_cast<ULONG>(text.size()), &needed) == 0) {
            text.resize(std::strlen(text.c_str()));
            warnings.push_back(call_.label() + ": 3MF reader warning " + std::to_string(code) + ": " +
                               oneLine(text));
        }
    }
    DWORD unit = NMR::MODELUNIT_MILLIMETER;
    call_.check(NMR::lib3mf_model_getunit(model_.get(), &unit), model_.get(), "reading the unit");
    const double scale = millimetresPerUnit(unit);
    Affine3 to_mm;
    for (int i = 0; i < 3; ++i) {
        to_mm.m[i][i] = scale;
    }
    return to_mm;
}

std::string ThreeMfLoader::objectName(NMR::PLib3MFBase* object, std::size_t item_number) const {
    ULONG needed = 0;
    std::string name;
    if (NMR::lib3mf_object_getnameutf8(object, nullptr, 0, &needed) == 0 && needed > 0) {
        name.assign(needed + 1, '\0');
        if (NMR::lib3mf_object_getnameutf8(object, name.data(), static_cast<ULONG>(name.size()), &needed) !=
            0) {
            name.clear();
        }
        name.resize(std::strlen(name.c_str()));
    }
    if (name.empty()) {
        name = stem_ + "_" + std::to_string(item_number);
    }
    return name;
}

void ThreeMfLoader::appendMesh(NMR::PLib3MFBase* mesh, const Affine3& to_mm, TriangleSoup& soup) {
    DWORD vertex_count = 0;
    DWORD triangle_count = 0;
    call_.check(NMR::lib3mf_meshobject_getvertexcount(mesh, &vertex_count), mesh, "reading a mesh");
    call_.check(NMR::lib3mf_meshobject_gettrianglecount(mesh, &triangle_count), mesh, "reading a mesh");
    vertices_.resize(vertex_count);
    triangles_.resize(triangle_count);
    if (vertex_count == 0 || triangle_count == 0) {
        return;
    }
    call_.check(NMR::lib3mf_meshobject_getvertices(mesh, vertices_.data(), vertex_count, nullptr), mesh,
                "reading vertices");
    call_.check(NMR::lib3mf_meshobject_gettriangleindices(mesh, triangles_.data(), triangle_count, nullptr),
                mesh, "reading triangles");
    std::vector<std::uint32_t> colors = meshColors(mesh, triangle_count);
    if (!colors.empty() || !soup.colors.empty()) {
        soup.colors.resize(soup.triangles.size(), 0);
        colors.resize(triangle_count, 0);
        soup.colors.insert(soup.colors.end(), colors.begin(), colors.end());
    }
    soup.triangles.reserve(soup.triangles.size() + triangle_count);
    for (const NMR::MODELMESHTRIANGLE& t : triangles_) {
        std::array<Vec3, 3>& out = soup.triangles.emplace_back();
        for (int k = 0; k < 3; ++k) {
            if (t.m_nIndices[k] >= vertex_count) {
                fail("triangle refers to vertex " + std::to_string(t.m_nIndices[k]) + " of " +
                     plural(vertex_count, "vertex", "vertices"));
            }
            const float* p = vertices_[t.m_nIndices[k]].m_fPosition;
            if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
                fail("non-finite vertex coordinate in object '" + soup.name + "'");
            }
            out[k] = to_mm.apply({p[0], p[1], p[2]});
        }
    }
}

void ThreeMfLoader::appendComponents(NMR::PLib3MFBase* object, const Affine3& to_mm, int depth,
                                     TriangleSoup& soup) {
    DWORD count = 0;
    call_.check(NMR::lib3mf_componentsobject_getcomponentcount(object, &count), object, "reading components");
    for (DWORD i = 0; i < count; ++i) {
        Lib3mfHandle component;
        call_.check(NMR::lib3mf_componentsobject_getcomponent(object, i, component.out()), object,
                    "reading a component");
        Lib3mfHandle child;
        call_.check(NMR::lib3mf_component_getobjectresource(component.get(), child.out()), component.get(),
                    "reading a component's object");
        NMR::MODELTRANSFORM transform{};
        call_.check(NMR::lib3mf_component_gettransform(component.get(), &transform), component.get(),
                    "reading a component transform");
        appendObject(child.get(), to_mm.after(toAffine(transform)), depth + 1, soup);
    }
}

void ThreeMfLoader::appendObject(NMR::PLib3MFBase* object, const Affine3& to_mm, int depth,
                                 TriangleSoup& soup) {
    if (depth > kMaxComponentDepth) {
        fail("components nested deeper than " + std::to_string(kMaxComponentDepth) + " levels");
    }
    BOOL is_mesh = 0;
    BOOL is_components = 0;
    call_.check(NMR::lib3mf_object_ismeshobject(object, &is_mesh), object, "reading an object");
    call_.check(NMR::lib3mf_object_iscomponentsobject(object, &is_components), object, "reading an object");
    if (is_mesh) {
        appendMesh(object, to_mm, soup);
    } else if (is_components) {
        appendComponents(object, to_mm, depth, soup);
    }
}

TriangleSoup ThreeMfLoader::readBuildItem(NMR::PLib3MFBase* item, std::size_t item_number,
                                          const Affine3& to_mm) {
    Lib3mfHandle object;
    call_.check(NMR::lib3mf_builditem_getobjectresource(item, object.out()), item, "reading a build item");
    NMR::MODELTRANSFORM transform{};
    call_.check(NMR::lib3mf_builditem_getobjecttransform(item, &transform), item,
                "reading a build item transform");
    TriangleSoup soup;
    soup.name = objectName(object.get(), item_number);
    appendObject(object.get(), to_mm.after(toAffine(transform)), 0, soup);
    return soup;
}

std::vector<TriangleSoup> ThreeMfLoader::load(const std::filesystem::path& file,
                                              std::vector<std::string>& warnings) {
    const Affine3 to_mm = open(file, warnings);
    painted_ = readPaintedFacets(file);
    Lib3mfHandle items;
    call_.check(NMR::lib3mf_model_getbuilditems(model_.get(), items.out()), model_.get(),
                "reading the build");
    std::vector<TriangleSoup> parts;
    BOOL has_next = 0;
    std::size_t item_count = 0;
    while (NMR::lib3mf_builditemiterator_movenext(items.get(), &has_next) == 0 && has_next) {
        Lib3mfHandle item;
        call_.check(NMR::lib3mf_builditemiterator_getcurrent(items.get(), item.out()), items.get(),
                    "reading a build item");
        TriangleSoup soup = readBuildItem(item.get(), ++item_count, to_mm);
        if (soup.triangles.empty()) {
            warnings.push_back(call_.label() + ": build item '" + soup.name + "' has no triangles; skipped");
            continue;
        }
        if (!soup.colors.empty())
            soup.colors.resize(soup.triangles.size(), 0);
        parts.push_back(std::move(soup));
    }
    if (parts.empty()) {
        fail("contains no triangles");
    }
    return parts;
}

}  // namespace

std::vector<TriangleSoup> readThreeMf(const std::filesystem::path& file, std::vector<std::string>& warnings) {
    const std::string label = file.string();
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(file, error);
    if (error) {
        throw InputError(label + ": cannot read model file: " + error.message());
    }
    if (size == 0) {
        throw InputError(label + ": empty file");
    }
    ThreeMfLoader loader(label, file.stem().string());
    return loader.load(file, warnings);
}

}  // namespace mixengine
