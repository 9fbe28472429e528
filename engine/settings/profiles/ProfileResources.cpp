#include "settings/profiles/ProfileResources.h"

#include <algorithm>
#include <system_error>

#include "common/Error.h"

namespace mixengine {
namespace fs = std::filesystem;
namespace {

/// Files under `dir` whose names end with `suffix`, sorted by path.
std::vector<fs::path> filesUnder(const fs::path& dir, std::string_view suffix) {
    std::vector<fs::path> files;
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
        return files;
    for (fs::recursive_directory_iterator it(dir, fs::directory_options::follow_directory_symlink, ec), end;
         !ec && it != end; it.increment(ec)) {
        if (it->is_regular_file(ec) && it->path().filename().string().ends_with(suffix))
            files.push_back(it->path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

template <typename T, typename IdOf>
void sortUnique(std::vector<T>& items, IdOf id_of) {
    // stable: among equal ids the earlier root (read first) stays first and is kept
    std::stable_sort(items.begin(), items.end(), [&](const T& a, const T& b) { return id_of(a) < id_of(b); });
    items.erase(
        std::unique(items.begin(), items.end(), [&](const T& a, const T& b) { return id_of(a) == id_of(b); }),
        items.end());
}

void readInstanceContainers(const fs::path& root, const std::set<std::string, std::less<>>& definition_ids,
                            ProfileResources& out) {
    for (const char* folder : {"variants", "quality", "intent"}) {
        for (const fs::path& path : filesUnder(root / folder, ".inst.cfg")) {
            try {
                InstCfgFile file = readInstCfgFile(path);
                if (!definition_ids.count(file.definition()))
                    continue;
                const std::string* type = file.meta("type");
                if (!type)
                    continue;
                if (*type == "variant")
                    out.variants.push_back(std::move(file));
                else if (*type == "quality")
                    out.qualities.push_back(std::move(file));
                else if (*type == "intent")
                    out.intents.push_back(std::move(file));
            } catch (const InputError& e) {
                out.problems.push_back(e.what());
            }
        }
    }
}

}  // namespace

ProfileResources loadProfileResources(const std::vector<fs::path>& roots,
                                      const std::set<std::string, std::less<>>& definition_ids) {
    ProfileResources out;
    for (const fs::path& root : roots) {
        readInstanceContainers(root, definition_ids, out);
        for (const fs::path& path : filesUnder(root / "materials", ".xml.fdm_material")) {
            try {
                out.materials.push_back(readMaterialFile(path));
            } catch (const InputError& e) {
                out.problems.push_back(e.what());
            }
        }
    }
    auto by_id = [](const InstCfgFile& f) -> const std::string& { return f.id; };
    sortUnique(out.variants, by_id);
    sortUnique(out.qualities, by_id);
    sortUnique(out.intents, by_id);
    sortUnique(out.materials, [](const MaterialProfile& m) -> const std::string& { return m.base_file; });
    return out;
}

std::vector<fs::path> profileRoots(const std::vector<fs::path>& search_path) {
    std::vector<fs::path> roots;
    for (const fs::path& dir : search_path) {
        for (const fs::path& candidate : {dir, dir.parent_path()}) {
            std::error_code ec;
            bool has = false;
            for (const char* folder : {"variants", "quality", "intent", "materials"})
                has = has || fs::is_directory(candidate / folder, ec);
            const fs::path canonical = fs::weakly_canonical(candidate, ec);
            if (has && std::find(roots.begin(), roots.end(), canonical) == roots.end())
                roots.push_back(canonical);
        }
    }
    return roots;
}

}  // namespace mixengine
