#include "scene_export.h"

#include <charconv>
#include <sstream>
#include <variant>

#include <nlohmann/json.hpp>

namespace radiant::bench {
namespace {

using Json = nlohmann::ordered_json;

Json vec(const Vec3& v) { return Json::array({v.x, v.y, v.z}); }

Json points(const std::vector<Vec3>& vs) {
    Json out = Json::array();
    for (const Vec3& v : vs) out.push_back(vec(v));
    return out;
}

const char* unit_name(LengthUnit u) {
    switch (u) {
        case LengthUnit::m:
            return "m";
        case LengthUnit::cm:
            return "cm";
        case LengthUnit::mm:
            return "mm";
        case LengthUnit::ft:
            return "ft";
        case LengthUnit::in:
            return "in";
    }
    return "m";
}

Json color(const Rgb& c) { return Json::array({c[0], c[1], c[2]}); }

Json material(const Material& m) {
    Json out;
    out["reflectance"] = m.rgb_reflectance ? color(m.reflectance) : Json(m.reflectance[0]);
    if (m.emission) {
        Json e;
        e[m.emission->kind == Emission::Kind::flux ? "flux" : "exitance"] = m.emission->value;
        if (m.emission->color) e["color"] = color(*m.emission->color);
        out["emission"] = e;
    }
    if (m.two_sided) out["two_sided"] = true;
    return out;
}

Json surface(const Surface& s) {
    Json out{{"name", s.name}, {"material", s.material}};
    if (const auto* polygon = std::get_if<Polygon>(&s.geometry)) {
        out["polygon"] = points(*polygon);
    } else if (const auto* mesh = std::get_if<MeshGeometry>(&s.geometry)) {
        out["mesh"] = {{"vertices", points(mesh->vertices)}, {"faces", mesh->faces}};
    } else {
        const auto& box = std::get<BoxGeometry>(s.geometry);
        out["box"] = {
            {"min", vec(box.min)}, {"max", vec(box.max)}, {"facing", box.facing_in ? "in" : "out"}};
    }
    return out;
}

Json luminaire(const Luminaire& l) {
    Json out{{"name", l.name}, {"position", vec(l.position)}};
    if (l.flux_lm) out["flux"] = *l.flux_lm;
    switch (l.distribution) {
        case Distribution::isotropic:
            out["distribution"] = "isotropic";
            break;
        case Distribution::lambertian:
            out["distribution"] = "lambertian";
            break;
        case Distribution::photometric:
            out["distribution"] = {{"ies", ies_text(l.photometry.value(), l.name)}};
            break;
    }
    out["aim"] = vec(l.aim);
    if (l.rotation_deg != 0) out["rotation"] = l.rotation_deg;
    if (l.color) out["color"] = color(*l.color);
    return out;
}

Json sensor(const SensorSet& s) {
    Json out{{"name", s.name}};
    if (s.workplane) {
        const Workplane& w = *s.workplane;
        Json rule{{"surfaces", w.surfaces}};
        if (w.height) rule["height"] = *w.height;
        if (w.border) rule["border"] = *w.border;
        if (w.spacing) rule["spacing"] = *w.spacing;
        out["workplane"] = rule;
    } else {
        out["normal"] = vec(s.normal);
        out["points"] = points(s.points);
    }
    return out;
}

bool is_flat(const Json& array) {
    for (const Json& e : array) {
        if (e.is_structured()) return false;
    }
    return true;
}

// An array of vertices or faces: arrays of numbers, packed several to a line.
bool is_table(const Json& array) {
    for (const Json& e : array) {
        if (!e.is_array() || !is_flat(e)) return false;
    }
    return true;
}

constexpr std::size_t kLineLength = 100;

// Objects one item a line; arrays of numbers (a vertex, a face) on one line, and arrays of those
// packed up to kLineLength columns (a million-triangle floor stays under the parser's 64 MiB).
void write(std::ostream& out, const Json& j, int depth) {
    const std::string pad(2 * static_cast<std::size_t>(depth + 1), ' ');
    if (j.is_array() && !j.empty() && is_table(j)) {
        out << "[\n" << pad;
        std::size_t column = pad.size();
        for (std::size_t k = 0; k < j.size(); ++k) {
            const std::string item = j[k].dump() + (k + 1 < j.size() ? "," : "");
            if (k > 0 && column + item.size() > kLineLength) {
                out << '\n' << pad;
                column = pad.size();
            }
            out << item;
            column += item.size();
        }
        out << '\n' << std::string(2 * static_cast<std::size_t>(depth), ' ') << ']';
    } else if (j.is_object() && !j.empty()) {
        out << "{\n";
        bool first = true;
        for (const auto& [key, value] : j.items()) {
            out << (first ? "" : ",\n") << pad << Json(key).dump() << ": ";
            write(out, value, depth + 1);
            first = false;
        }
        out << '\n' << std::string(2 * static_cast<std::size_t>(depth), ' ') << '}';
    } else if (j.is_array() && !j.empty() && !is_flat(j)) {
        out << "[\n";
        for (std::size_t k = 0; k < j.size(); ++k) {
            out << (k ? ",\n" : "") << pad;
            write(out, j[k], depth + 1);
        }
        out << '\n' << std::string(2 * static_cast<std::size_t>(depth), ' ') << ']';
    } else {
        out << j.dump();
    }
}

void append_number(std::string& out, double v) {
    char buffer[32];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
    out.append(buffer, end);
}

// Ten numbers a line, as LM-63 files usually are.
void append_numbers(std::string& out, const std::vector<double>& values) {
    for (std::size_t k = 0; k < values.size(); ++k) {
        append_number(out, values[k]);
        out += (k + 1) % 10 == 0 || k + 1 == values.size() ? '\n' : ' ';
    }
}

}  // namespace

std::string ies_text(const PhotometricTable& table, const std::string& label) {
    std::string out =
        "IESNA:LM-63-2002\n[TEST] " + label + ", written by radiant-bench\nTILT=NONE\n";
    out += "1 -1 1 " + std::to_string(table.gamma_deg.size()) + " " +
           std::to_string(table.c_deg.size()) + " 1 2 0 0 0\n1 1 0\n";
    append_numbers(out, table.gamma_deg);
    append_numbers(out, table.c_deg);
    append_numbers(out, table.candela);
    return out;
}

std::string scene_document(const Scene& scene) {
    Json doc{{"format", "radiant-scene/1"}};
    if (!scene.name.empty()) doc["name"] = scene.name;
    doc["units"] = unit_name(scene.units);
    Json materials = Json::object();
    for (const Material& m : scene.materials) materials[m.name] = material(m);
    doc["materials"] = materials;
    Json surfaces = Json::array();
    for (const Surface& s : scene.surfaces) surfaces.push_back(surface(s));
    doc["surfaces"] = surfaces;
    if (!scene.luminaires.empty()) {
        Json luminaires = Json::array();
        for (const Luminaire& l : scene.luminaires) luminaires.push_back(luminaire(l));
        doc["luminaires"] = luminaires;
    }
    if (!scene.sensors.empty()) {
        Json sensors = Json::array();
        for (const SensorSet& s : scene.sensors) sensors.push_back(sensor(s));
        doc["sensors"] = sensors;
    }
    Json settings{{"tolerance", scene.settings.tolerance}};
    if (scene.settings.max_seconds) settings["max_seconds"] = *scene.settings.max_seconds;
    if (scene.settings.method != "auto") settings["method"] = scene.settings.method;
    doc["settings"] = settings;
    std::ostringstream out;
    write(out, doc, 0);
    out << '\n';
    return out.str();
}

}  // namespace radiant::bench
