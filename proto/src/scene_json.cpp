#include "radiant/proto/scene_json.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <set>
#include <sstream>
#include <string_view>

#include "import/scene_relative_file.h"
#include "import/surface_import.h"
#include "json_text.h"
#include "photometry/ies_reader.h"
#include "photometry/ldt_reader.h"
#include "radiant/proto/significant_digits.h"
#include "radiant/solve.h"

namespace radiant::proto {
namespace {

using Json = nlohmann::ordered_json;
using Ptr = Json::json_pointer;

constexpr std::string_view kFormat = "radiant-scene/1";

/// The part of a pointer that names one scene entity: "/surfaces/3", "/materials/wall",
/// "/settings". Entities are the unit at which structural damage hides semantic problems.
std::string entity_of(const std::string& pointer) {
    constexpr std::string_view lists[] = {"materials", "surfaces",  "luminaires",
                                          "sensors",   "observers", "light_scenes"};
    const std::size_t first = pointer.find('/', 1);
    if (first == std::string::npos) return pointer;
    const std::string_view head = std::string_view(pointer).substr(1, first - 1);
    if (std::find(std::begin(lists), std::end(lists), head) == std::end(lists))
        return pointer.substr(0, first);
    return pointer.substr(0, pointer.find('/', first + 1));
}

/// Reads the structure of a scene document. Values that cannot be read are reported and replaced
/// by placeholders, so that every entity keeps its index and later checks keep their pointers.
class SceneReader {
public:
    SceneReader(const ParseLimits& limits, std::optional<std::filesystem::path> scene_directory)
        : limits_(limits), scene_directory_(std::move(scene_directory)) {}

    Scene read(const Json& root);

    std::vector<Problem> problems_;
    std::set<std::string> broken_;        ///< entities with a value that could not be read
    std::set<std::size_t> grid_sensors_;  ///< sensor sets whose points come from a grid
    /// Per engine surface: its document index and, for an imported model, the key naming it.
    std::vector<std::pair<std::size_t, std::string>> surface_origins_;
    std::size_t unlisted_ = 0;  ///< problems beyond kMaxListedProblems, counted only
    std::size_t faces_ = 0;     ///< polygons, mesh faces and box sides read so far

private:
    void report(const Ptr& p, std::string message, bool breaks = true) {
        std::string pointer = p.to_string();
        if (breaks) broken_.insert(entity_of(pointer));
        if (problems_.size() >= kMaxListedProblems) {
            ++unlisted_;
            return;
        }
        problems_.push_back({std::move(pointer), std::move(message)});
    }

    /// Unknown keys are reported but do not hide other problems: the known keys still parse.
    void check_keys(const Json& object, const Ptr& p,
                    std::initializer_list<std::string_view> keys) {
        for (const auto& item : object.items()) {
            if (std::find(keys.begin(), keys.end(), item.key()) == keys.end()) {
                report(p / item.key(), "unknown key", false);
            }
        }
    }

    const Json* member(const Json& object, const Ptr& p, const char* key, bool required) {
        const auto it = object.find(key);
        if (it != object.end()) return &*it;
        if (required) report(p / key, std::string("missing required key \"") + key + "\"");
        return nullptr;
    }

    bool object(const Json& j, const Ptr& p, const char* what) {
        if (j.is_object()) return true;
        report(p, std::string(what) + " must be an object");
        return false;
    }

    bool array(const Json& j, const Ptr& p, const char* what) {
        if (j.is_array()) return true;
        report(p, std::string(what) + " must be an array");
        return false;
    }

    double number(const Json& j, const Ptr& p, const char* what) {
        if (j.is_number()) return j.get<double>();
        report(p, std::string(what) + " must be a number");
        return std::numeric_limits<double>::quiet_NaN();
    }

    /// An integer in [min, max]; like JSON Schema, 2.0 counts as an integer.
    std::optional<long long> integer(const Json& j, const Ptr& p, const char* what, long long min,
                                     long long max) {
        const double d = j.is_number() ? j.get<double>() : 0.5;
        if (std::floor(d) != d || d < static_cast<double>(min)) {
            report(p, std::string(what) + " must be an integer >= " + std::to_string(min));
            return std::nullopt;
        }
        if (d > static_cast<double>(max)) {
            report(p, std::string(what) + " must be at most " + std::to_string(max));
            return std::nullopt;
        }
        return static_cast<long long>(d);
    }

    bool boolean(const Json& j, const Ptr& p, const char* what) {
        if (j.is_boolean()) return j.get<bool>();
        report(p, std::string(what) + " must be true or false");
        return false;
    }

    std::string string(const Json& j, const Ptr& p, const char* what) {
        if (j.is_string()) return j.get<std::string>();
        report(p, std::string(what) + " must be a string");
        return {};
    }

    Vec3 vec3(const Json& j, const Ptr& p, const char* what) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        if (!j.is_array() || j.size() != 3) {
            report(p, std::string(what) + " must be an array of 3 numbers");
            return {nan, nan, nan};
        }
        Vec3 v;
        for (std::size_t c = 0; c < 3; ++c)
            v[static_cast<int>(c)] = number(j[c], p / c, "coordinate");
        return v;
    }

    std::vector<Vec3> points(const Json& j, const Ptr& p, const char* what) {
        std::vector<Vec3> out;
        if (!array(j, p, what)) return out;
        out.reserve(j.size());
        for (std::size_t k = 0; k < j.size(); ++k) out.push_back(vec3(j[k], p / k, "a point"));
        return out;
    }

    Rgb rgb(const Json& j, const Ptr& p, const char* what) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        if (!j.is_array() || j.size() != 3) {
            report(p, std::string(what) + " must be an array of 3 numbers");
            return {nan, nan, nan};
        }
        Rgb out;
        for (std::size_t c = 0; c < 3; ++c) out[c] = number(j[c], p / c, what);
        return out;
    }

    Material material(const std::string& name, const Json& j, const Ptr& p);
    std::optional<Emission> emission(const Json& j, const Ptr& p);
    void add_surfaces(Scene& scene, const Json& j, const Ptr& p, std::size_t index);
    Surface surface(const Json& j, const Ptr& p);
    MeshGeometry mesh(const Json& j, const Ptr& p);
    BoxGeometry box(const Json& j, const Ptr& p);
    Luminaire luminaire(const Json& j, const Ptr& p);
    /// The keys every light source may carry: group, maintenance_factor, ra.
    SourceDesign source_design(const Json& j, const Ptr& p);
    LuminousShape luminous_area(const Json& j, const Ptr& p);
    Requirement requirement(const Json& j, const Ptr& p);
    Observer observer(const Json& j, const Ptr& p);
    LightScene light_scene(const Json& j, const Ptr& p);
    std::optional<double> optional_number(const Json& j, const Ptr& p, const char* key) {
        if (const Json* x = member(j, p, key, false)) return number(*x, p / key, key);
        return std::nullopt;
    }
    std::optional<PhotometricTable> photometry(const Json& j, const Ptr& p);
    SensorSet sensor(const Json& j, const Ptr& p, std::size_t index);
    Workplane workplane(const Json& j, const Ptr& p);
    std::vector<Vec3> grid(const Json& j, const Ptr& p);
    Settings settings(const Json& j, const Ptr& p);

    /// What is left of `limit` once `used` is taken.
    static std::size_t left(std::size_t limit, std::size_t used) {
        return limit - std::min(limit, used);
    }
    void count_geometry(const Surface& s);

    const ParseLimits& limits_;
    std::optional<std::filesystem::path> scene_directory_;
    /// Totals read so far: grids and models are checked against what is left of the scene's
    /// limits before they are expanded, so many small ones cannot add up to a huge scene.
    std::size_t vertices_ = 0, sensor_points_ = 0;
};

Scene SceneReader::read(const Json& root) {
    Scene scene;
    const Ptr p;
    check_keys(root, p,
               {"format", "name", "units", "materials", "surfaces", "luminaires", "sensors",
                "observers", "light_scenes", "settings"});
    if (const Json* j = member(root, p, "format", true)) {
        if (!j->is_string() || j->get<std::string>() != kFormat) {
            report(p / "format", "format must be \"" + std::string(kFormat) + "\"");
        }
    }
    if (const Json* j = member(root, p, "name", false)) scene.name = string(*j, p / "name", "name");
    if (const Json* j = member(root, p, "units", false)) {
        static const std::pair<const char*, LengthUnit> units[] = {{"m", LengthUnit::m},
                                                                   {"cm", LengthUnit::cm},
                                                                   {"mm", LengthUnit::mm},
                                                                   {"ft", LengthUnit::ft},
                                                                   {"in", LengthUnit::in}};
        const auto it = std::find_if(std::begin(units), std::end(units),
                                     [&](const auto& u) { return *j == u.first; });
        if (it == std::end(units)) {
            report(p / "units", "units must be one of m, cm, mm, ft, in");
        } else {
            scene.units = it->second;
        }
    }
    if (const Json* j = member(root, p, "materials", true);
        j && object(*j, p / "materials", "materials")) {
        for (const auto& item : j->items()) {
            scene.materials.push_back(
                material(item.key(), item.value(), p / "materials" / item.key()));
        }
    }
    if (const Json* j = member(root, p, "surfaces", true);
        j && array(*j, p / "surfaces", "surfaces")) {
        for (std::size_t i = 0; i < j->size(); ++i) {
            add_surfaces(scene, (*j)[i], p / "surfaces" / i, i);
        }
    }
    if (const Json* j = member(root, p, "luminaires", false);
        j && array(*j, p / "luminaires", "luminaires")) {
        for (std::size_t i = 0; i < j->size(); ++i) {
            scene.luminaires.push_back(luminaire((*j)[i], p / "luminaires" / i));
        }
    }
    if (const Json* j = member(root, p, "sensors", false);
        j && array(*j, p / "sensors", "sensors")) {
        for (std::size_t i = 0; i < j->size(); ++i) {
            scene.sensors.push_back(sensor((*j)[i], p / "sensors" / i, i));
        }
    }
    if (const Json* j = member(root, p, "observers", false);
        j && array(*j, p / "observers", "observers")) {
        for (std::size_t i = 0; i < j->size(); ++i) {
            scene.observers.push_back(observer((*j)[i], p / "observers" / i));
        }
    }
    if (const Json* j = member(root, p, "light_scenes", false);
        j && array(*j, p / "light_scenes", "light_scenes")) {
        for (std::size_t i = 0; i < j->size(); ++i) {
            scene.light_scenes.push_back(light_scene((*j)[i], p / "light_scenes" / i));
        }
    }
    if (const Json* j = member(root, p, "settings", false)) {
        scene.settings = settings(*j, p / "settings");
    }
    return scene;
}

Material SceneReader::material(const std::string& name, const Json& j, const Ptr& p) {
    Material m;
    m.name = name;
    if (!object(j, p, "a material")) return m;
    check_keys(j, p, {"reflectance", "emission", "two_sided"});
    if (const Json* r = member(j, p, "reflectance", true)) {
        if (r->is_array()) {
            m.reflectance = rgb(*r, p / "reflectance", "reflectance");
            m.rgb_reflectance = true;
        } else if (r->is_number()) {
            m.reflectance.fill(r->get<double>());
        } else {
            report(p / "reflectance", "reflectance must be a number or an array of 3 numbers");
        }
    }
    if (const Json* e = member(j, p, "emission", false)) m.emission = emission(*e, p / "emission");
    if (const Json* t = member(j, p, "two_sided", false))
        m.two_sided = boolean(*t, p / "two_sided", "two_sided");
    return m;
}

std::optional<Emission> SceneReader::emission(const Json& j, const Ptr& p) {
    if (!object(j, p, "emission")) return std::nullopt;
    check_keys(j, p, {"exitance", "flux", "color", "group", "maintenance_factor", "ra"});
    const bool exitance = j.contains("exitance"), flux = j.contains("flux");
    if (exitance == flux) {
        report(p, "emission needs exactly one of exitance or flux");
        return std::nullopt;
    }
    Emission e;
    e.kind = flux ? Emission::Kind::flux : Emission::Kind::exitance;
    const char* key = flux ? "flux" : "exitance";
    e.value = number(j[key], p / key, key);
    if (const Json* c = member(j, p, "color", false)) e.color = rgb(*c, p / "color", "color");
    e.design = source_design(j, p);
    return e;
}

SourceDesign SceneReader::source_design(const Json& j, const Ptr& p) {
    SourceDesign d;
    if (const Json* g = member(j, p, "group", false)) d.group = string(*g, p / "group", "group");
    d.maintenance_factor = optional_number(j, p, "maintenance_factor");
    d.ra = optional_number(j, p, "ra");
    return d;
}

/// A surface that imports a model becomes one engine surface per material of the model. A model
/// that cannot be read leaves a placeholder, so that later surfaces keep their pointers.
void SceneReader::add_surfaces(Scene& scene, const Json& j, const Ptr& p, std::size_t index) {
    static const std::pair<const char*, ImportKind> kinds[] = {
        {"obj", ImportKind::obj},
        {"obj_file", ImportKind::obj_file},
        {"gltf", ImportKind::gltf},
        {"gltf_file", ImportKind::gltf_file}};
    const auto* kind = std::find_if(std::begin(kinds), std::end(kinds), [&](const auto& k) {
        return j.is_object() && j.contains(k.first);
    });
    const bool other_geometry =
        j.is_object() && (j.contains("polygon") || j.contains("mesh") || j.contains("box"));
    const bool two_models =
        kind != std::end(kinds) &&
        std::any_of(kind + 1, std::end(kinds), [&](const auto& k) { return j.contains(k.first); });
    if (kind == std::end(kinds) || other_geometry || two_models) {
        surface_origins_.emplace_back(index, "");
        scene.surfaces.push_back(surface(j, p));
        count_geometry(scene.surfaces.back());
        scene.surfaces.back().pointer = p.to_string();
        return;
    }
    check_keys(j, p, {"name", "material", "mtl", kind->first});
    ImportRequest request;
    request.kind = kind->second;
    request.unit = scene.units;
    request.scene_directory = scene_directory_;
    request.max_bytes = limits_.max_bytes;
    request.budget = {left(limits_.scene.max_vertices, vertices_), left(limits_.max_faces, faces_)};
    const std::size_t problems_before = problems_.size();
    if (const Json* n = member(j, p, "name", true)) request.name = string(*n, p / "name", "name");
    if (const Json* m = member(j, p, "material", false))
        request.material = string(*m, p / "material", "material");
    if (const Json* m = member(j, p, "mtl", false)) {
        if (request.kind == ImportKind::obj || request.kind == ImportKind::obj_file) {
            request.mtl = string(*m, p / "mtl", "mtl");
        } else {
            report(p / "mtl", "mtl goes with obj or obj_file");
        }
    }
    request.value = string(j[kind->first], p / kind->first, kind->first);
    auto imported = problems_.size() == problems_before
                        ? import_surface(request)
                        : std::variant<ImportedSurfaces, std::string>(std::string());
    if (auto* problem = std::get_if<std::string>(&imported)) {
        if (!problem->empty()) report(p / kind->first, std::move(*problem));
        surface_origins_.emplace_back(index, "");
        scene.surfaces.emplace_back();
        return;
    }
    auto& [surfaces, materials] = std::get<ImportedSurfaces>(imported);
    for (Surface& s : surfaces) {
        count_geometry(s);
        surface_origins_.emplace_back(index, kind->first);
        s.pointer = p.to_string();
        scene.surfaces.push_back(std::move(s));
    }
    for (Material& m : materials) scene.materials.push_back(std::move(m));
}

void SceneReader::count_geometry(const Surface& s) {
    if (const auto* polygon = std::get_if<Polygon>(&s.geometry)) {
        vertices_ += polygon->size();
        faces_ += 1;
    } else if (const auto* mesh = std::get_if<MeshGeometry>(&s.geometry)) {
        vertices_ += mesh->vertices.size();
        faces_ += mesh->faces.size();
    } else {
        vertices_ += 8;
        faces_ += 6;
    }
}

Surface SceneReader::surface(const Json& j, const Ptr& p) {
    Surface s;
    if (!object(j, p, "a surface")) return s;
    check_keys(j, p,
               {"name", "material", "polygon", "mesh", "box", "obj", "obj_file", "gltf",
                "gltf_file", "mtl"});
    if (j.contains("mtl")) report(p / "mtl", "mtl goes with obj or obj_file", false);
    if (const Json* n = member(j, p, "name", true)) s.name = string(*n, p / "name", "name");
    if (const Json* m = member(j, p, "material", true)) {
        s.material = string(*m, p / "material", "material");
    }
    int kinds = 0;
    for (const char* key : {"polygon", "mesh", "box", "obj", "obj_file", "gltf", "gltf_file"})
        kinds += int{j.contains(key)};
    if (kinds != 1) {
        report(
            p,
            "a surface needs exactly one of polygon, mesh, box, obj, obj_file, gltf or gltf_file");
    } else if (j.contains("polygon")) {
        s.geometry = points(j["polygon"], p / "polygon", "polygon");
    } else if (j.contains("mesh")) {
        s.geometry = mesh(j["mesh"], p / "mesh");
    } else {
        s.geometry = box(j["box"], p / "box");
    }
    return s;
}

MeshGeometry SceneReader::mesh(const Json& j, const Ptr& p) {
    MeshGeometry m;
    if (!object(j, p, "mesh")) return m;
    check_keys(j, p, {"vertices", "faces"});
    if (const Json* v = member(j, p, "vertices", true))
        m.vertices = points(*v, p / "vertices", "vertices");
    const Json* faces = member(j, p, "faces", true);
    if (!faces || !array(*faces, p / "faces", "faces")) return m;
    for (std::size_t k = 0; k < faces->size(); ++k) {
        const Json& face = (*faces)[k];
        std::vector<int>& out = m.faces.emplace_back();
        if (!array(face, p / "faces" / k, "a face")) continue;
        for (std::size_t n = 0; n < face.size(); ++n) {
            const auto index = integer(face[n], p / "faces" / k / n, "a face index", 0,
                                       std::numeric_limits<int>::max());
            out.push_back(index ? static_cast<int>(*index) : -1);
        }
    }
    return m;
}

BoxGeometry SceneReader::box(const Json& j, const Ptr& p) {
    BoxGeometry b;
    if (!object(j, p, "box")) return b;
    check_keys(j, p, {"min", "max", "facing"});
    if (const Json* v = member(j, p, "min", true)) b.min = vec3(*v, p / "min", "min");
    if (const Json* v = member(j, p, "max", true)) b.max = vec3(*v, p / "max", "max");
    if (const Json* f = member(j, p, "facing", false)) {
        if (*f == "in" || *f == "out") {
            b.facing_in = *f == "in";
        } else {
            report(p / "facing", "facing must be \"in\" or \"out\"");
        }
    }
    return b;
}

Luminaire SceneReader::luminaire(const Json& j, const Ptr& p) {
    Luminaire l;
    if (!object(j, p, "a luminaire")) return l;
    check_keys(j, p,
               {"name", "position", "flux", "distribution", "aim", "rotation", "color", "group",
                "maintenance_factor", "ra", "luminous_area"});
    if (const Json* n = member(j, p, "name", true)) l.name = string(*n, p / "name", "name");
    if (const Json* v = member(j, p, "position", true))
        l.position = vec3(*v, p / "position", "position");
    if (const Json* d = member(j, p, "distribution", false)) {
        if (*d == "isotropic" || *d == "lambertian") {
            l.distribution = *d == "isotropic" ? Distribution::isotropic : Distribution::lambertian;
        } else if (d->is_object()) {
            l.distribution = Distribution::photometric;
            l.photometry = photometry(*d, p / "distribution");
        } else {
            report(p / "distribution",
                   "distribution must be \"isotropic\", \"lambertian\", {\"ies\": ...} or "
                   "{\"ldt\": ...}");
        }
    }
    // A table carries its own flux; the simple distributions need one.
    const bool table = l.distribution == Distribution::photometric;
    if (const Json* f = member(j, p, "flux", !table)) l.flux_lm = number(*f, p / "flux", "flux");
    if (const Json* a = member(j, p, "aim", false)) l.aim = vec3(*a, p / "aim", "aim");
    if (const Json* r = member(j, p, "rotation", false)) {
        l.rotation_deg = number(*r, p / "rotation", "rotation");
    }
    if (const Json* c = member(j, p, "color", false)) l.color = rgb(*c, p / "color", "color");
    l.design = source_design(j, p);
    if (const Json* a = member(j, p, "luminous_area", false)) {
        l.luminous_area = luminous_area(*a, p / "luminous_area");
    }
    return l;
}

/// {"length", "width"} (a rectangle, length along C0) or {"diameter"} (a disc), each with an
/// optional "height" of luminous sides.
LuminousShape SceneReader::luminous_area(const Json& j, const Ptr& p) {
    LuminousShape shape;
    if (!object(j, p, "luminous_area")) return shape;
    check_keys(j, p, {"length", "width", "diameter", "height"});
    const bool disc = j.contains("diameter");
    if (disc == (j.contains("length") || j.contains("width"))) {
        report(p, "luminous_area needs length and width, or diameter");
        return shape;
    }
    if (disc) {
        shape.round = true;
        shape.length = shape.width = number(j["diameter"], p / "diameter", "diameter");
    } else {
        if (const Json* x = member(j, p, "length", true))
            shape.length = number(*x, p / "length", "length");
        if (const Json* x = member(j, p, "width", true))
            shape.width = number(*x, p / "width", "width");
    }
    shape.height = optional_number(j, p, "height").value_or(0);
    return shape;
}

std::optional<PhotometricTable> SceneReader::photometry(const Json& j, const Ptr& p) {
    check_keys(j, p, {"ies", "ldt", "ies_file", "ldt_file"});
    const char* key = nullptr;
    int keys = 0;
    for (const char* k : {"ies", "ldt", "ies_file", "ldt_file"}) {
        if (j.contains(k)) key = k, ++keys;
    }
    if (keys != 1) {
        report(p, "a photometric distribution needs exactly one of ies, ldt, ies_file or ldt_file");
        return std::nullopt;
    }
    const std::string_view kind = key;
    std::string text = string(j[key], p / key, key);
    if (text.empty()) {
        if (j[key].is_string()) report(p / key, "the " + std::string(kind) + " text is empty");
        return std::nullopt;
    }
    if (kind.ends_with("_file")) {
        std::string bytes;
        if (auto problem =
                read_scene_relative_file(scene_directory_, text, limits_.max_bytes, bytes)) {
            report(p / key, std::move(*problem));
            return std::nullopt;
        }
        text = std::move(bytes);
    }
    auto table = kind.starts_with("ies") ? read_ies(text) : read_ldt(text);
    if (auto* problem = std::get_if<std::string>(&table)) {
        report(p / key, std::move(*problem));
        return std::nullopt;
    }
    return std::get<PhotometricTable>(std::move(table));
}

SensorSet SceneReader::sensor(const Json& j, const Ptr& p, std::size_t index) {
    SensorSet s;
    if (!object(j, p, "a sensor set")) return s;
    check_keys(j, p, {"name", "normal", "points", "grid", "workplane", "kind", "requirement"});
    if (const Json* n = member(j, p, "name", true)) s.name = string(*n, p / "name", "name");
    // A work plane faces up unless told otherwise.
    if (const Json* n = member(j, p, "normal", !j.contains("workplane"))) {
        s.normal = vec3(*n, p / "normal", "normal");
    }
    const int kinds =
        int{j.contains("points")} + int{j.contains("grid")} + int{j.contains("workplane")};
    if (kinds != 1) {
        report(p, "a sensor set needs exactly one of points, grid or workplane");
    } else if (j.contains("points")) {
        s.points = points(j["points"], p / "points", "points");
        sensor_points_ += s.points.size();
    } else if (j.contains("grid")) {
        grid_sensors_.insert(index);
        s.points = grid(j["grid"], p / "grid");
        if (j["grid"].is_object() && !s.points.empty()) {
            const Json& g = j["grid"];
            s.grid_area =
                GridArea{vec3(g["origin"], p / "grid" / "origin", "origin"),
                         vec3(g["u"], p / "grid" / "u", "u"), vec3(g["v"], p / "grid" / "v", "v")};
        }
    } else {
        s.workplane = workplane(j["workplane"], p / "workplane");
    }
    if (const Json* k = member(j, p, "kind", false)) {
        const auto kind = k->is_string() ? sensor_kind_named(k->get<std::string>()) : std::nullopt;
        if (!kind) {
            report(p / "kind",
                   "kind must be one of planar, vertical, cylindrical, semi-cylindrical");
        } else {
            s.kind = *kind;
        }
    }
    if (const Json* r = member(j, p, "requirement", false)) {
        s.requirement = requirement(*r, p / "requirement");
    }
    return s;
}

Requirement SceneReader::requirement(const Json& j, const Ptr& p) {
    Requirement r;
    if (!object(j, p, "requirement")) return r;
    check_keys(j, p, {"activity", "em_lx", "u0", "ugr_l", "ra"});
    if (const Json* a = member(j, p, "activity", false))
        r.activity = string(*a, p / "activity", "activity");
    r.em_lx = optional_number(j, p, "em_lx");
    r.u0 = optional_number(j, p, "u0");
    r.ugr_l = optional_number(j, p, "ugr_l");
    r.ra = optional_number(j, p, "ra");
    return r;
}

Observer SceneReader::observer(const Json& j, const Ptr& p) {
    Observer o;
    if (!object(j, p, "an observer")) return o;
    check_keys(j, p, {"name", "position", "view", "task"});
    if (const Json* n = member(j, p, "name", true)) o.name = string(*n, p / "name", "name");
    if (const Json* x = member(j, p, "position", true))
        o.position = vec3(*x, p / "position", "position");
    if (const Json* x = member(j, p, "view", true)) o.view = vec3(*x, p / "view", "view");
    if (const Json* t = member(j, p, "task", false)) o.task = string(*t, p / "task", "task");
    return o;
}

LightScene SceneReader::light_scene(const Json& j, const Ptr& p) {
    LightScene s;
    if (!object(j, p, "a light scene")) return s;
    check_keys(j, p, {"name", "dimming"});
    if (const Json* n = member(j, p, "name", true)) s.name = string(*n, p / "name", "name");
    if (const Json* d = member(j, p, "dimming", true); d && object(*d, p / "dimming", "dimming")) {
        for (const auto& item : d->items()) {
            s.dimming.emplace_back(item.key(),
                                   number(item.value(), p / "dimming" / item.key(), "a dimming"));
        }
    }
    return s;
}

Workplane SceneReader::workplane(const Json& j, const Ptr& p) {
    Workplane w;
    if (!object(j, p, "workplane")) return w;
    check_keys(j, p, {"surfaces", "height", "border", "spacing"});
    if (const Json* names = member(j, p, "surfaces", true);
        names && array(*names, p / "surfaces", "surfaces")) {
        for (std::size_t k = 0; k < names->size(); ++k) {
            w.surfaces.push_back(string((*names)[k], p / "surfaces" / k, "a surface name"));
        }
    }
    for (auto [key, value] : {std::pair{"height", &w.height}, std::pair{"border", &w.border},
                              std::pair{"spacing", &w.spacing}}) {
        if (const Json* x = member(j, p, key, false)) *value = number(*x, p / key, key);
    }
    return w;
}

/// Cell centres of the grid, row-major with u fastest (contract §2).
std::vector<Vec3> SceneReader::grid(const Json& j, const Ptr& p) {
    if (!object(j, p, "grid")) return {};
    check_keys(j, p, {"origin", "u", "v", "nu", "nv"});
    const std::size_t problems_before = problems_.size();
    Vec3 origin, u, v;
    std::optional<long long> nu, nv;
    const auto max = static_cast<long long>(limits_.scene.max_sensor_points);
    if (const Json* x = member(j, p, "origin", true)) origin = vec3(*x, p / "origin", "origin");
    if (const Json* x = member(j, p, "u", true)) u = vec3(*x, p / "u", "u");
    if (const Json* x = member(j, p, "v", true)) v = vec3(*x, p / "v", "v");
    if (const Json* x = member(j, p, "nu", true)) nu = integer(*x, p / "nu", "nu", 1, max);
    if (const Json* x = member(j, p, "nv", true)) nv = integer(*x, p / "nv", "nv", 1, max);
    if (problems_.size() != problems_before || !nu || !nv) return {};
    // Checked against the total before expanding, so neither one hostile grid nor many small
    // ones can exhaust memory.
    const auto room = static_cast<long long>(left(limits_.scene.max_sensor_points, sensor_points_));
    if (*nu > room / *nv) {
        const std::string before =
            sensor_points_ > 0
                ? " (with the " + std::to_string(sensor_points_) + " sensor points before it)"
                : "";
        report(p, "grid has " + std::to_string(*nu * *nv) + " points" + before +
                      ", over the limit of " + std::to_string(max) + " sensor points");
        sensor_points_ += static_cast<std::size_t>(*nu) * static_cast<std::size_t>(*nv);
        return {};
    }
    sensor_points_ += static_cast<std::size_t>(*nu * *nv);
    std::vector<Vec3> out;
    out.reserve(static_cast<std::size_t>(*nu * *nv));
    for (long long jv = 0; jv < *nv; ++jv) {
        for (long long iu = 0; iu < *nu; ++iu) {
            out.push_back(origin + (static_cast<double>(iu) + 0.5) / static_cast<double>(*nu) * u +
                          (static_cast<double>(jv) + 0.5) / static_cast<double>(*nv) * v);
        }
    }
    return out;
}

Settings SceneReader::settings(const Json& j, const Ptr& p) {
    Settings s;
    if (!object(j, p, "settings")) return s;
    check_keys(j, p,
               {"tolerance", "max_seconds", "method", "strict", "maintenance_factor", "digits"});
    s.maintenance_factor = optional_number(j, p, "maintenance_factor");
    if (const Json* t = member(j, p, "tolerance", false)) {
        s.tolerance = number(*t, p / "tolerance", "tolerance");
    }
    if (const Json* t = member(j, p, "max_seconds", false)) {
        s.max_seconds = number(*t, p / "max_seconds", "max_seconds");
    }
    if (const Json* t = member(j, p, "strict", false))
        s.strict = boolean(*t, p / "strict", "strict");
    if (const Json* d = member(j, p, "digits", false)) {
        if (const auto digits = integer(*d, p / "digits", "digits", 1, kMaxDigits)) {
            s.digits = static_cast<int>(*digits);
        }
    }
    if (const Json* m = member(j, p, "method", false)) {
        // The engine's own list, so the parser never accepts a method the engine lacks.
        const std::vector<std::string> methods = solver_names();
        if (m->is_string() &&
            std::find(methods.begin(), methods.end(), m->get<std::string>()) != methods.end()) {
            s.method = m->get<std::string>();
        } else {
            std::string list;
            for (const auto& name : methods) list += (list.empty() ? "" : ", ") + name;
            report(p / "method", "method must be one of " + list);
        }
    }
    return s;
}

/// Cuts `problems` to kMaxListedProblems, counting the cut ones (and `uncounted` more) in a last
/// problem.
void limit_problems(std::vector<Problem>& problems, std::size_t uncounted) {
    if (problems.size() > kMaxListedProblems) {
        uncounted += problems.size() - kMaxListedProblems;
        problems.resize(kMaxListedProblems);
    }
    if (uncounted > 0) {
        problems.push_back({"", std::to_string(uncounted) + " more problems are not listed"});
    }
}

/// check_scene sees a grid only as its expanded points; point the user at the grid instead.
std::string document_pointer(const std::string& pointer, const std::set<std::size_t>& grids) {
    constexpr std::string_view prefix = "/sensors/";
    if (pointer.rfind(prefix, 0) != 0) return pointer;
    const std::size_t slash = pointer.find('/', prefix.size());
    if (slash == std::string::npos || pointer.compare(slash, 7, "/points") != 0) return pointer;
    const std::size_t index = std::stoul(pointer.substr(prefix.size(), slash - prefix.size()));
    return grids.contains(index) ? pointer.substr(0, slash) + "/grid" : pointer;
}

/// check_scene sees surfaces as the engine does: an imported model may be several surfaces, each
/// a mesh. Point the user at the document's surface and, for a model, its key and face.
void to_document_surface(Problem& problem,
                         const std::vector<std::pair<std::size_t, std::string>>& origins,
                         const Scene& scene) {
    constexpr std::string_view prefix = "/surfaces/";
    const std::string& pointer = problem.pointer;
    if (pointer.rfind(prefix, 0) != 0 || pointer.size() == prefix.size()) return;
    const std::size_t slash = std::min(pointer.find('/', prefix.size()), pointer.size());
    const std::size_t engine = std::stoul(pointer.substr(prefix.size(), slash - prefix.size()));
    if (engine >= origins.size()) return;
    const auto& [index, key] = origins[engine];
    const std::string rest = pointer.substr(slash);
    const std::string surface = std::string(prefix) + std::to_string(index);
    constexpr std::string_view faces = "/mesh/faces/";
    if (key.empty() || rest.rfind("/mesh", 0) != 0) {
        problem.pointer = surface + rest;
        return;
    }
    std::string where = "surface \"" + scene.surfaces[engine].name + "\"";
    if (rest.rfind(faces, 0) == 0) {
        where += " face " + rest.substr(faces.size(), rest.find('/', faces.size()) - faces.size());
    }
    problem.pointer = surface + "/" + key;
    problem.message = where + ": " + problem.message;
}

}  // namespace

ParseOutcome parse_scene(std::string_view json_text, const ParseLimits& limits,
                         const std::optional<std::filesystem::path>& scene_directory) {
    ParseOutcome outcome;
    if (json_text.size() > limits.max_bytes) {
        outcome.problems.push_back({"", "the document is " + std::to_string(json_text.size()) +
                                            " bytes, over the limit of " +
                                            std::to_string(limits.max_bytes)});
        outcome.refusal = Refusal::over_budget;
        return outcome;
    }
    auto parsed = parse_json_text(json_text, limits.json);
    if (auto* refused = std::get_if<JsonRefusal>(&parsed)) {
        outcome.problems.push_back(std::move(refused->problem));
        outcome.refusal = refused->over_budget ? Refusal::over_budget : Refusal::not_json;
        return outcome;
    }
    const Json& root = std::get<Json>(parsed);
    outcome.refusal = Refusal::scene;
    if (!root.is_object()) {
        outcome.problems.push_back({"", "a scene must be a JSON object"});
        return outcome;
    }
    SceneReader reader(limits, scene_directory);
    Scene scene = reader.read(root);
    outcome.problems = std::move(reader.problems_);
    // Placeholders for unreadable values would only produce echoes of the same problem.
    for (Problem& p : check_scene(scene, limits.scene)) {
        p.pointer = document_pointer(p.pointer, reader.grid_sensors_);
        to_document_surface(p, reader.surface_origins_, scene);
        if (reader.broken_.contains(entity_of(p.pointer))) continue;
        outcome.problems.push_back(std::move(p));
    }
    // The faces of the whole scene; the engine's own checks count its other totals.
    if (reader.faces_ > limits.max_faces) {
        outcome.problems.push_back({"/surfaces", std::to_string(reader.faces_) +
                                                     " faces, over the limit of " +
                                                     std::to_string(limits.max_faces)});
    }
    limit_problems(outcome.problems, reader.unlisted_);
    // Work planes need the checked floors; task areas their grids.
    if (outcome.problems.empty()) outcome.problems = expand_workplanes(scene, limits.scene);
    if (outcome.problems.empty()) outcome.problems = expand_task_areas(scene, limits.scene);
    // The expanded points are known only now.
    if (outcome.problems.empty()) outcome.problems = check_sensor_totals(scene, limits.scene);
    if (outcome.problems.empty()) {
        outcome.scene = std::move(scene);
        outcome.refusal = Refusal::none;
    }
    return outcome;
}

ParseOutcome load_scene_file(const std::filesystem::path& path, const ParseLimits& limits) {
    auto unreadable = [&](const std::string& why) {
        ParseOutcome outcome;
        outcome.problems.push_back({"", "cannot read " + path.string() + ": " + why});
        return outcome;
    };
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) return unreadable(ec.message());
    if (size > limits.max_bytes) {
        ParseOutcome outcome;
        outcome.problems.push_back({"", "the file is " + std::to_string(size) +
                                            " bytes, over the limit of " +
                                            std::to_string(limits.max_bytes)});
        outcome.refusal = Refusal::over_budget;
        return outcome;
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) return unreadable("cannot open the file");
    // One byte more than measured tells whether the file grew in between.
    std::string text(static_cast<std::size_t>(size) + 1, '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    if (in.bad()) return unreadable("read error");
    if (static_cast<std::size_t>(in.gcount()) != size)
        return unreadable("the file changed while it was read");
    text.resize(static_cast<std::size_t>(size));
    return parse_scene(text, limits, path.parent_path());
}

std::string format_problem(const std::string& file, const Problem& problem) {
    return file + ": " + problem.pointer + ": " + problem.message;
}

}  // namespace radiant::proto
