#include "radiant/proto/honeybee.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <map>
#include <string_view>
#include <utility>

#include "import/polygon_with_holes.h"
#include "json_text.h"
#include "radiant/proto/scene_json.h"

namespace radiant::proto {
namespace {

using Json = nlohmann::ordered_json;
using Ptr = Json::json_pointer;

/// Reflectances used when a face has no usable modifier (contract-facing, see the README).
struct Default {
    const char* material;
    double reflectance;
    bool two_sided;
};
constexpr Default kFloor{"default-floor", 0.2, false};
constexpr Default kWall{"default-wall", 0.5, false};
constexpr Default kCeiling{"default-ceiling", 0.8, false};
constexpr Default kAperture{"default-aperture", 0.08, false};  // glass: most light leaves
constexpr Default kDoor{"default-door", 0.5, false};
constexpr Default kShade{"default-shade", 0.35, true};

/// Ear clipping takes up to cubic time in the vertices of a face with holes; real faces (a wall
/// and its windows) have tens.
constexpr std::size_t kMaxVerticesWithHoles = 1000;

class Converter {
public:
    Json convert(const Json& model);

    std::vector<Problem> problems_;
    std::vector<std::string> surface_pointers_;  ///< per emitted surface: its HBJSON pointer

private:
    void report(const Ptr& p, std::string message) {
        problems_.push_back({p.to_string(), std::move(message)});
    }

    /// `key` of `object`, when `object` is an object that has it.
    static const Json* get(const Json& object, const char* key) {
        if (!object.is_object()) return nullptr;
        const auto it = object.find(key);
        return it == object.end() ? nullptr : &*it;
    }

    /// The entry of `table` that `value` names, when `value` is a string that names one.
    template <typename T, std::size_t N>
    static const std::pair<std::string_view, T>* named(
        const std::pair<std::string_view, T> (&table)[N], const Json* value) {
        if (!value || !value->is_string()) return nullptr;
        const std::string& name = value->get_ref<const std::string&>();
        const auto it = std::find_if(std::begin(table), std::end(table),
                                     [&](const auto& entry) { return entry.first == name; });
        return it == std::end(table) ? nullptr : it;
    }

    /// The value at the end of a chain of keys, when every step is an object that has it.
    static const Json* path(const Json& object, std::initializer_list<const char*> keys) {
        const Json* j = &object;
        for (const char* key : keys) {
            j = get(*j, key);
            if (!j) return nullptr;
        }
        return j;
    }

    const Json* array(const Json& object, const Ptr& p, const char* key) {
        const Json* a = get(object, key);
        if (a && !a->is_array()) {
            report(p / key, std::string(key) + " must be an array");
            return nullptr;
        }
        return a;
    }

    std::optional<Json> point(const Json& j, const Ptr& p) {
        if (!j.is_array() || j.size() != 3 ||
            !std::all_of(j.begin(), j.end(), [](const Json& c) { return c.is_number(); })) {
            report(p, "a point must be an array of 3 numbers");
            return std::nullopt;
        }
        return Json::array({j[0], j[1], j[2]});
    }

    void modifiers(const Json& model);
    std::string material(const Json& object, const Default& fallback);
    void face3d(const Json& object, const Ptr& p, const Default& fallback, bool reverse);
    static std::optional<Json> mesh_with_holes(const Json& polygon, const std::vector<Json>& holes);
    void room(const Json& room, const Ptr& p);
    void shades(const Json& object, const Ptr& p, const char* key);
    void sensor_grids(const Json& grids, const Ptr& p);

    std::map<std::string, Json> modifier_materials_;  ///< usable modifiers by identifier
    Json materials_ = Json::object();
    Json surfaces_ = Json::array();
    Json sensors_ = Json::array();
};

std::string name_of(const Json& object, const std::string& fallback) {
    for (const char* key : {"identifier", "display_name"}) {
        const auto it = object.find(key);
        if (it != object.end() && it->is_string() && !it->get<std::string>().empty())
            return it->get<std::string>();
    }
    return fallback;
}

Json Converter::convert(const Json& model) {
    const Ptr root;
    const Json* type = get(model, "type");
    if (!type || *type != "Model")
        report(root / "type", "a Honeybee model has \"type\": \"Model\"");
    constexpr std::pair<std::string_view, std::string_view> units[] = {{"Meters", "m"},
                                                                       {"Millimeters", "mm"},
                                                                       {"Centimeters", "cm"},
                                                                       {"Feet", "ft"},
                                                                       {"Inches", "in"}};
    std::string unit = "m";
    if (const Json* u = get(model, "units")) {
        const auto* it = named(units, u);
        if (!it) {
            report(root / "units",
                   "units must be Meters, Millimeters, Centimeters, Feet or Inches");
        } else {
            unit = it->second;
        }
    }
    modifiers(model);
    if (const Json* rooms = array(model, root, "rooms")) {
        for (std::size_t i = 0; i < rooms->size(); ++i) room((*rooms)[i], root / "rooms" / i);
    }
    shades(model, root, "orphaned_shades");
    const Ptr radiance = root / "properties" / "radiance";
    if (const Json* r = path(model, {"properties", "radiance"})) {
        if (const Json* grids = array(*r, radiance, "sensor_grids")) {
            sensor_grids(*grids, radiance / "sensor_grids");
        }
    }
    if (problems_.empty() && surfaces_.empty()) report(root, "the model has no faces or shades");
    Json scene = Json::object();
    scene["format"] = "radiant-scene/1";
    scene["name"] = name_of(model, "honeybee-model");
    scene["units"] = unit;
    scene["materials"] = materials_;
    scene["surfaces"] = surfaces_;
    if (!sensors_.empty()) scene["sensors"] = sensors_;
    return scene;
}

void Converter::modifiers(const Json& model) {
    const Ptr p = Ptr("/properties/radiance");
    const Json* radiance = path(model, {"properties", "radiance"});
    const Json* list = radiance ? array(*radiance, p, "modifiers") : nullptr;
    if (!list) return;
    for (std::size_t i = 0; i < list->size(); ++i) {
        const Json& m = (*list)[i];
        const Ptr at = p / "modifiers" / i;
        const Json* type = get(m, "type");
        const Json* id = get(m, "identifier");
        if (!type || !type->is_string() || !id || !id->is_string()) {
            report(at, "a modifier needs a string type and identifier");
            continue;
        }
        std::string kind = type->get<std::string>();
        std::transform(kind.begin(), kind.end(), kind.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (kind != "plastic" && kind != "metal") continue;  // glass, trans, light...: defaults
        Json rgb = Json::array();
        for (const char* key : {"r_reflectance", "g_reflectance", "b_reflectance"}) {
            const Json* r = get(m, key);
            const double v = r && r->is_number() ? r->get<double>() : -1;
            if (!(v >= 0 && v < 1)) {
                report(at / key, std::string(key) + " must be a number in [0, 1)");
                rgb.push_back(0);
            } else {
                rgb.push_back(v);
            }
        }
        const bool gray = rgb[0] == rgb[1] && rgb[1] == rgb[2];
        modifier_materials_[id->get<std::string>()] = {{"reflectance", gray ? rgb[0] : rgb}};
    }
}

/// The scene material of a face, aperture, door or shade: its modifier, else the default.
std::string Converter::material(const Json& object, const Default& fallback) {
    const Json* modifier = path(object, {"properties", "radiance", "modifier"});
    if (modifier && modifier->is_string()) {
        const auto it = modifier_materials_.find(modifier->get<std::string>());
        if (it != modifier_materials_.end()) {
            Json m = it->second;
            if (fallback.two_sided) m["two_sided"] = true;
            const std::string name = it->first + (fallback.two_sided ? " (two-sided)" : "");
            materials_[name] = m;
            return name;
        }
    }
    Json m = {{"reflectance", fallback.reflectance}};
    if (fallback.two_sided) m["two_sided"] = true;
    materials_[fallback.material] = m;
    return fallback.material;
}

/// One polygon from the object's `geometry` (a Face3D); `reverse` turns it to face the room.
void Converter::face3d(const Json& object, const Ptr& p, const Default& fallback, bool reverse) {
    const Json* geometry = get(object, "geometry");
    const Json* boundary = geometry ? get(*geometry, "boundary") : nullptr;
    if (!boundary || !boundary->is_array() || boundary->size() < 3) {
        report(p / "geometry" / "boundary", "a Face3D needs a boundary of at least 3 points");
        return;
    }
    const Ptr at = p / "geometry";
    const std::size_t problems_before = problems_.size();
    Json polygon = Json::array();
    for (std::size_t k = 0; k < boundary->size(); ++k) {
        if (auto v = point((*boundary)[k], at / "boundary" / k)) polygon.push_back(*v);
    }
    std::vector<Json> holes;
    const Json* hole_list = array(*geometry, at, "holes");
    for (std::size_t h = 0; hole_list && h < hole_list->size(); ++h) {
        const Json& ring = (*hole_list)[h];
        if (!ring.is_array() || ring.size() < 3) {
            report(at / "holes" / h, "a hole needs at least 3 points");
            continue;
        }
        Json hole = Json::array();
        for (std::size_t k = 0; k < ring.size(); ++k) {
            if (auto v = point(ring[k], at / "holes" / h / k)) hole.push_back(*v);
        }
        holes.push_back(std::move(hole));
    }
    if (problems_.size() != problems_before) return;
    if (reverse) std::reverse(polygon.begin(), polygon.end());
    Json surface = {{"name", name_of(object, p.to_string())},
                    {"material", material(object, fallback)}};
    std::size_t ring_vertices = polygon.size();
    for (const Json& hole : holes) ring_vertices += hole.size();
    if (holes.empty()) {
        surface["polygon"] = polygon;
    } else if (ring_vertices > kMaxVerticesWithHoles) {
        report(at / "holes", "a face with holes may have at most " +
                                 std::to_string(kMaxVerticesWithHoles) + " vertices, not " +
                                 std::to_string(ring_vertices));
        return;
    } else if (auto mesh = mesh_with_holes(polygon, holes)) {
        surface["mesh"] = std::move(*mesh);
    } else {
        report(at / "holes", "the holes do not lie inside the boundary as separate rings");
        return;
    }
    surfaces_.push_back(std::move(surface));
    surface_pointers_.push_back(p.to_string());
}

/// A face with holes as a `mesh` surface: its boundary and hole vertices, triangulated.
std::optional<Json> Converter::mesh_with_holes(const Json& polygon,
                                               const std::vector<Json>& holes) {
    const auto vec = [](const Json& v) {
        return Vec3{v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
    };
    std::vector<Vec3> outer;
    Json vertices = polygon;
    for (const Json& v : polygon) outer.push_back(vec(v));
    std::vector<std::vector<Vec3>> rings;
    for (const Json& hole : holes) {
        rings.emplace_back();
        for (const Json& v : hole) {
            rings.back().push_back(vec(v));
            vertices.push_back(v);
        }
    }
    const auto triangles = triangulate_with_holes(outer, rings);
    if (!triangles) return std::nullopt;
    Json faces = Json::array();
    for (const auto& t : *triangles) {
        Json face = Json::array();
        for (const int index : t) face.push_back(static_cast<std::uint64_t>(index));
        faces.push_back(std::move(face));
    }
    return Json{{"vertices", std::move(vertices)}, {"faces", std::move(faces)}};
}

void Converter::room(const Json& room, const Ptr& p) {
    if (!room.is_object()) {
        report(p, "a room must be an object");
        return;
    }
    const Json* faces = array(room, p, "faces");
    if (!faces) report(p / "faces", "a room needs faces");
    for (std::size_t k = 0; faces && k < faces->size(); ++k) {
        const Json& face = (*faces)[k];
        const Ptr at = p / "faces" / k;
        static const std::pair<std::string_view, const Default*> types[] = {
            {"Floor", &kFloor},
            {"Wall", &kWall},
            {"RoofCeiling", &kCeiling},
            {"AirBoundary", nullptr}};
        const auto* it = named(types, get(face, "face_type"));
        if (!it) {
            report(at / "face_type", "face_type must be Floor, Wall, RoofCeiling or AirBoundary");
            continue;
        }
        if (!it->second) continue;  // an air boundary lets light through: no surface
        face3d(face, at, *it->second, true);
        for (const auto& [key, fallback] :
             {std::pair<const char*, const Default*>{"apertures", &kAperture}, {"doors", &kDoor}}) {
            const Json* subfaces = array(face, at, key);
            for (std::size_t s = 0; subfaces && s < subfaces->size(); ++s) {
                face3d((*subfaces)[s], at / key / s, *fallback, true);
                shades((*subfaces)[s], at / key / s, "indoor_shades");
            }
        }
        shades(face, at, "indoor_shades");
    }
    shades(room, p, "indoor_shades");
}

void Converter::shades(const Json& object, const Ptr& p, const char* key) {
    const Json* list = array(object, p, key);
    for (std::size_t s = 0; list && s < list->size(); ++s) {
        face3d((*list)[s], p / key / s, kShade, false);
    }
}

/// One sensor set per grid, or per grid and direction when its sensors differ in direction.
void Converter::sensor_grids(const Json& grids, const Ptr& p) {
    for (std::size_t g = 0; g < grids.size(); ++g) {
        const Ptr at = p / g;
        const Json* sensors = array(grids[g], at, "sensors");
        if (!sensors || sensors->empty()) {
            report(at / "sensors", "a sensor grid needs sensors");
            continue;
        }
        std::vector<std::pair<Json, Json>> sets;  // direction → points, in order of appearance
        // Looked up by value: a linear search would be quadratic in the number of directions.
        std::map<std::array<double, 3>, std::size_t> set_of_direction;
        for (std::size_t s = 0; s < sensors->size(); ++s) {
            const Json& sensor = (*sensors)[s];
            const Json* pos_json = get(sensor, "pos");
            const Json* dir_json = get(sensor, "dir");
            const auto pos = point(pos_json ? *pos_json : Json(), at / "sensors" / s / "pos");
            const auto dir = point(dir_json ? *dir_json : Json(), at / "sensors" / s / "dir");
            if (!pos || !dir) continue;
            const std::array<double, 3> key{(*dir)[0].get<double>(), (*dir)[1].get<double>(),
                                            (*dir)[2].get<double>()};
            const auto [slot, added] = set_of_direction.try_emplace(key, sets.size());
            if (added) sets.emplace_back(*dir, Json::array());
            sets[slot->second].second.push_back(*pos);
        }
        const std::string name = name_of(grids[g], "grid " + std::to_string(g));
        for (std::size_t k = 0; k < sets.size(); ++k) {
            sensors_.push_back(
                {{"name", sets.size() == 1 ? name : name + " #" + std::to_string(k + 1)},
                 {"normal", sets[k].first},
                 {"points", sets[k].second}});
        }
    }
}

}  // namespace

HoneybeeOutcome honeybee_to_scene(std::string_view hbjson_text) {
    HoneybeeOutcome outcome;
    auto parsed = parse_json_text(hbjson_text);
    if (auto* refused = std::get_if<JsonRefusal>(&parsed)) {
        outcome.problems.push_back(std::move(refused->problem));
        return outcome;
    }
    const Json& model = std::get<Json>(parsed);
    if (!model.is_object()) {
        outcome.problems.push_back({"", "a Honeybee model must be a JSON object"});
        return outcome;
    }
    Converter converter;
    Json scene = converter.convert(model);
    outcome.problems = std::move(converter.problems_);
    if (!outcome.problems.empty()) return outcome;
    // The scene's own checks (planarity, zero area...), reported at the Honeybee object.
    for (Problem p : parse_scene(scene.dump()).problems) {
        constexpr std::string_view prefix = "/surfaces/";
        if (p.pointer.rfind(prefix, 0) == 0) {
            const std::size_t index = std::stoul(p.pointer.substr(prefix.size()));
            if (index < converter.surface_pointers_.size()) {
                p.pointer = converter.surface_pointers_[index] + "/geometry/boundary";
            }
        }
        outcome.problems.push_back(std::move(p));
    }
    if (outcome.problems.empty()) outcome.scene = std::move(scene);
    return outcome;
}

}  // namespace radiant::proto
