// GET /v1/jobs/{id}/sensors.csv, plan.png and view.png: files made from a finished job's stored
// result (and its stored mesh and scene), never by solving again. Each handler returns its work
// for the session to run off the I/O threads.
#include "radiant/server/handlers.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>

#include "job_errors.h"
#include "radiant/picture/room_view.h"
#include "radiant/picture/sensor_plan.h"
#include "radiant/proto/result_reader.h"
#include "radiant/proto/scene_json.h"
#include "radiant/proto/sensors_csv.h"
#include "radiant/proto/significant_digits.h"
#include "radiant/server/compact_mesh.h"

namespace radiant::server::handlers {
namespace {

/// Picture sides, and all the pixels of one picture: a view holds ~40 bytes per pixel while it
/// is drawn, so one picture stays under 100 MB.
constexpr int kMinPicturePixels = 16, kMaxPictureSide = 2048;
constexpr long kMaxViewPixels = 1L << 21;

/// The finished job's stored result (read back), or the answer saying why there is none.
std::variant<Result, Response> finished_result(ServiceContext& ctx, const Request& request,
                                               const std::string& id) {
    const auto job = ctx.jobs.find(id);
    if (!job) return unknown_job(request, id);
    if (job->status == JobStatus::queued) return not_ready(request, id);
    if (job->status == JobStatus::running) {
        return error_response(request, http::status::not_found, "not_ready",
                              "job " + id + " is running; its files are made from its result");
    }
    const auto document = ctx.store.result(id);
    if (!document) {
        return error_response(
            request, http::status::not_found, "no_result",
            "job " + id + " was " + to_string(job->status) + " before it produced a result");
    }
    proto::ResultReadOutcome read = proto::read_result(*document);
    if (!read.ok()) {
        throw std::runtime_error("the stored result of job " + id +
                                 " does not read: " + read.problems.front().pointer + ": " +
                                 read.problems.front().message);
    }
    if (read.result->status == SolveStatus::failed) {
        return error_response(request, http::status::not_found, "no_result",
                              "the solve of job " + id + " failed: " + read.result->error);
    }
    return std::move(*read.result);
}

/// The query of a picture: every parameter known, every value in range; the first problem is
/// kept as the answer.
class QueryReader {
public:
    QueryReader(const Request& request, const Query& query,
                std::initializer_list<std::string_view> known)
        : request_(request), query_(query) {
        for (const auto& [key, value] : query) {
            if (std::find(known.begin(), known.end(), key) == known.end()) {
                refuse("unknown query parameter \"" + key + "\"");
            }
        }
    }

    const std::optional<Response>& problem() const { return problem_; }

    std::optional<std::string> text(const char* key) const {
        const auto it = query_.find(key);
        if (it == query_.end()) return std::nullopt;
        return it->second;
    }

    /// A number in [min, max]; `fallback` when absent.
    double number(const char* key, double fallback, double min, double max) {
        const auto value = text(key);
        if (!value) return fallback;
        const auto read = parse(*value);
        if (!read || !(*read >= min && *read <= max)) {
            refuse(std::string(key) + " must be a number from " + short_text(min) + " to " +
                   short_text(max));
            return fallback;
        }
        return *read;
    }

    /// "x,y,z" with finite numbers.
    std::optional<Vec3> vec3(const char* key) {
        const auto value = text(key);
        if (!value) return std::nullopt;
        std::array<double, 3> xyz{};
        std::string_view rest = *value;
        for (std::size_t k = 0; k < 3; ++k) {
            const std::size_t comma = k < 2 ? rest.find(',') : rest.size();
            const auto read =
                comma == std::string_view::npos ? std::nullopt : parse(rest.substr(0, comma));
            if (!read) {
                refuse(std::string(key) + " must be three numbers x,y,z (metres)");
                return std::nullopt;
            }
            xyz[k] = *read;
            rest.remove_prefix(std::min(rest.size(), comma + 1));
        }
        return Vec3{xyz[0], xyz[1], xyz[2]};
    }

    /// Absent, "0" or "false": false; "", "1" or "true": true.
    bool flag(const char* key) {
        const auto value = text(key);
        if (!value || *value == "0" || *value == "false") return false;
        if (value->empty() || *value == "1" || *value == "true") return true;
        refuse(std::string(key) + " must be true or false");
        return false;
    }

    void refuse(const std::string& message) {
        if (!problem_) {
            problem_ =
                error_response(request_, http::status::bad_request, "invalid_query", message);
        }
    }

private:
    static std::optional<double> parse(std::string_view text) {
        double out = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
        if (text.empty() || ec != std::errc{} || end != text.data() + text.size() ||
            !std::isfinite(out)) {
            return std::nullopt;
        }
        return out;
    }

    static std::string short_text(double value) {
        std::array<char, 32> text{};
        const auto [end, ec] = std::to_chars(text.data(), text.data() + text.size(), value);
        return std::string(text.data(), ec == std::errc{} ? end : text.data());
    }

    const Request& request_;
    const Query& query_;
    std::optional<Response> problem_;
};

Response png_response(const Request& request, const picture::Image& image) {
    return text_response(request, http::status::ok, image.png(), "image/png");
}

Response sensors_csv(ServiceContext& ctx, const Request& request, const std::string& id) {
    auto stored = finished_result(ctx, request, id);
    if (auto* answer = std::get_if<Response>(&stored)) return std::move(*answer);
    const Result& result = std::get<Result>(stored);
    for (const SensorResult& set : result.sensors) {
        if (set.points.empty() && !set.illuminance.empty()) {
            return error_response(
                request, http::status::not_found, "no_points",
                "the result of job " + id + " was stored without its sensor points");
        }
    }
    // The stored numbers as they are: they were rounded when the result was written.
    Response response = text_response(request, http::status::ok,
                                      proto::sensors_csv(result.sensors, proto::kMaxDigits),
                                      "text/csv; charset=utf-8; header=present");
    response.set(http::field::content_disposition, "inline; filename=\"" + id + "-sensors.csv\"");
    return response;
}

Response plan_png(ServiceContext& ctx, const Request& request, const std::string& id,
                  const Query& query) {
    QueryReader q(request, query, {"sensors", "size", "max_lux"});
    const int size = static_cast<int>(q.number("size", 800, 100, kMaxPictureSide));
    const double max_lux = q.number("max_lux", 0, 0, 1e12);
    if (q.problem()) return *q.problem();
    auto stored = finished_result(ctx, request, id);
    if (auto* answer = std::get_if<Response>(&stored)) return std::move(*answer);
    const Result& result = std::get<Result>(stored);
    const auto name = q.text("sensors");
    const auto set = std::find_if(result.sensors.begin(), result.sensors.end(),
                                  [&](const SensorResult& s) { return !name || s.name == *name; });
    if (set == result.sensors.end()) {
        return error_response(
            request, http::status::not_found, "no_sensors",
            name ? "no sensor set named \"" + *name + "\"" : "the scene has no sensors");
    }
    if (set->points.empty()) {
        return error_response(request, http::status::not_found, "no_points",
                              "the result has no points for sensor set \"" + set->name + "\"");
    }
    return png_response(request, picture::draw_sensor_plan(
                                     picture::sensor_plan_of(result.scene, *set, max_lux), size));
}

Response view_png(ServiceContext& ctx, const Request& request, const std::string& id,
                  const Query& query) {
    QueryReader q(
        request, query,
        {"eye", "target", "up", "fov", "width", "height", "falsecolor", "max_lux", "exposure"});
    const std::optional<Vec3> eye = q.vec3("eye"), target = q.vec3("target"), up = q.vec3("up");
    picture::Camera camera;
    camera.vertical_fov_degrees = q.number("fov", 60, 1, 179);
    camera.width = static_cast<int>(q.number("width", 800, kMinPicturePixels, kMaxPictureSide));
    camera.height = static_cast<int>(q.number("height", 600, kMinPicturePixels, kMaxPictureSide));
    if (static_cast<long>(camera.width) * camera.height > kMaxViewPixels) {
        q.refuse("width × height must be at most " + std::to_string(kMaxViewPixels) + " pixels");
    }
    picture::ViewStyle style;
    style.falsecolor = q.flag("falsecolor");
    style.max_lux = q.number("max_lux", 0, 0, 1e12);
    style.exposure = q.number("exposure", 0, 0, 1e12);
    if (q.problem()) return *q.problem();

    auto stored = finished_result(ctx, request, id);
    if (auto* answer = std::get_if<Response>(&stored)) return std::move(*answer);
    Result& result = std::get<Result>(stored);
    const auto snapshot = ctx.jobs.snapshot(id);
    const auto job = ctx.store.find(id, true);
    if (!snapshot || !job) {
        return error_response(request, http::status::not_found, "no_result",
                              "job " + id + " has no stored mesh");
    }
    result.mesh = expand(snapshot->mesh());
    const proto::ParseOutcome scene = proto::parse_scene(job->scene_json);
    if (!scene.ok()) throw std::runtime_error("the stored scene of job " + id + " does not parse");
    const picture::Camera fallback = picture::default_camera(*result.mesh);
    camera.eye = eye.value_or(fallback.eye);
    camera.target = target.value_or(fallback.target);
    camera.up = up.value_or(camera.up);
    if (const auto problem = picture::camera_problem(camera)) {
        return error_response(request, http::status::bad_request, "invalid_query", *problem);
    }
    return png_response(request, picture::draw_view(result, *scene.scene, camera, style));
}

}  // namespace

DeferredResponse get_sensors_csv(ServiceContext& ctx, const Request& request,
                                 const std::string& id) {
    return [&ctx, request, id] { return sensors_csv(ctx, request, id); };
}

DeferredResponse get_plan_png(ServiceContext& ctx, const Request& request, const std::string& id,
                              const Query& query) {
    return [&ctx, request, id, query] { return plan_png(ctx, request, id, query); };
}

DeferredResponse get_view_png(ServiceContext& ctx, const Request& request, const std::string& id,
                              const Query& query) {
    return [&ctx, request, id, query] { return view_png(ctx, request, id, query); };
}

}  // namespace radiant::server::handlers
