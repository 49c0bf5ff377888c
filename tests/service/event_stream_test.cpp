// What an event stream sends, without sockets: progress, mesh and radiosity events in one id
// sequence, each mesh once per version, Last-Event-ID resume, and done at the end.
#include "radiant/server/event_stream.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "radiant/proto/base64.h"

namespace {

using namespace radiant::server;
using nlohmann::json;

JobRecord running_job() {
    JobRecord job;
    job.id = "abc";
    job.status = JobStatus::running;
    return job;
}

/// The float32 values of a base64 array of an event.
std::vector<float> floats(const json& base64) {
    const auto bytes = radiant::proto::decode_base64(base64.get<std::string>());
    EXPECT_TRUE(bytes && bytes->size() % 4 == 0);
    std::vector<float> out(bytes ? bytes->size() / 4 : 0);
    if (bytes) std::memcpy(out.data(), bytes->data(), 4 * out.size());
    return out;
}

/// The data of the first `name` event in `text`.
json event_data(const std::string& text, const std::string& name) {
    const std::size_t at = text.find("data: ", text.find("event: " + name + "\n")) + 6;
    return json::parse(text.substr(at, text.find('\n', at) - at));
}

/// A one-triangle snapshot whose radiosity is `value`; `values_event_id` 0: new values.
std::shared_ptr<const JobSnapshot> snapshot(std::uint64_t version, std::uint64_t mesh_version,
                                            std::uint64_t mesh_event_id,
                                            std::uint64_t radiosity_event_id, double value,
                                            std::uint64_t values_event_id = 0, bool final = false) {
    auto mesh = std::make_shared<radiant::SolvedMesh>();
    mesh->vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh->triangles = {{0, 1, 2}};
    mesh->triangle_surface = {0};
    mesh->triangle_radiosity = {value};
    mesh->vertex_radiosity = {value, value, value};
    SnapshotInfo info;
    info.version = version;
    info.mesh_version = mesh_version;
    info.mesh_event_id = mesh_event_id;
    info.radiosity_event_id = radiosity_event_id;
    info.values_event_id = values_event_id ? values_event_id : radiosity_event_id;
    info.final = final;
    return std::make_shared<const JobSnapshot>("abc", info, std::move(mesh));
}

/// The event names in `text`, in order.
std::string names(const std::string& text) {
    std::string out;
    for (std::size_t at = text.find("event: "); at != std::string::npos;
         at = text.find("event: ", at + 1)) {
        out += text.substr(at + 7, text.find('\n', at) - at - 7) + " ";
    }
    return out;
}

TEST(EventStream, ProgressThenDoneOnce) {
    EventStream stream;
    JobRecord job = running_job();
    EXPECT_EQ(stream.next(job, nullptr), "");  // nothing reported yet
    job.progress.sequence = 3;
    job.progress.fraction = 0.5;
    const std::string progress = stream.next(job, nullptr);
    EXPECT_TRUE(progress.starts_with("event: progress\nid: 3\ndata: {")) << progress;
    EXPECT_TRUE(progress.ends_with("}\n\n"));
    EXPECT_EQ(stream.next(job, nullptr), "");  // unchanged: nothing new
    job.status = JobStatus::done;
    job.progress.sequence = 4;
    const std::string end = stream.next(job, nullptr);
    EXPECT_NE(end.find("event: progress\nid: 4\n"), std::string::npos);
    EXPECT_NE(end.find("event: done\nid: 5\ndata: {\"id\":\"abc\",\"status\":\"done\"}\n\n"),
              std::string::npos)
        << end;
    EXPECT_TRUE(stream.finished());
    EXPECT_EQ(stream.next(job, nullptr), "");
}

TEST(EventStream, LastEventIdSkipsWhatTheClientHas) {
    EventStream stream(5);
    JobRecord job = running_job();
    job.progress.sequence = 5;
    EXPECT_EQ(stream.next(job, nullptr), "");
    job.progress.sequence = 6;
    EXPECT_NE(stream.next(job, nullptr).find("id: 6"), std::string::npos);
}

TEST(EventStream, MeshOncePerVersionBeforeItsRadiosityInIdOrder) {
    EventStream stream;
    JobRecord job = running_job();
    job.progress.sequence = 3;
    const std::string first = stream.next(job, snapshot(1, 1, 1, 2, 10.0).get());
    EXPECT_EQ(names(first), "mesh radiosity progress ");
    EXPECT_NE(first.find("event: mesh\nid: 1\n"), std::string::npos) << first;
    EXPECT_NE(first.find("event: radiosity\nid: 2\n"), std::string::npos) << first;
    const json radiosity = event_data(first, "radiosity");
    EXPECT_EQ(radiosity["mesh_version"], 1);
    EXPECT_EQ(radiosity["encoding"], "base64-le");
    EXPECT_EQ(floats(radiosity["triangle_radiosity"]), std::vector<float>({10.0f}));
    EXPECT_EQ(floats(radiosity["vertex_radiosity"]).size(), 3u);
    const json mesh = event_data(first, "mesh");
    EXPECT_EQ(floats(mesh["vertices"]), std::vector<float>({0, 0, 0, 1, 0, 0, 0, 1, 0}));

    // Same mesh, new values: only the radiosity.
    job.progress.sequence = 5;
    EXPECT_EQ(names(stream.next(job, snapshot(2, 1, 1, 4, 20.0).get())), "radiosity progress ");
    // New geometry: its mesh first.
    EXPECT_EQ(names(stream.next(job, snapshot(3, 2, 6, 7, 30.0).get())), "mesh radiosity ");
    EXPECT_EQ(stream.next(job, snapshot(3, 2, 6, 7, 30.0).get()), "");
}

TEST(EventStream, AResumedClientGetsTheMeshOnlyIfItMissedIt) {
    JobRecord job = running_job();
    job.progress.sequence = 4;
    const auto latest = snapshot(2, 1, 1, 5, 20.0);
    EXPECT_EQ(names(EventStream(3).next(job, latest.get())), "progress radiosity ");  // saw mesh 1
    EXPECT_EQ(names(EventStream(0).next(job, latest.get())), "mesh progress radiosity ");
    const auto remeshed = snapshot(3, 2, 6, 7, 30.0);
    EXPECT_EQ(names(EventStream(5).next(job, remeshed.get())), "mesh radiosity ");
}

TEST(EventStream, TheFinalRadiosityComesBeforeDone) {
    EventStream stream;
    JobRecord job = running_job();
    job.status = JobStatus::done;
    job.progress.sequence = 9;
    const std::string text = stream.next(job, snapshot(4, 1, 1, 8, 40.0).get());
    EXPECT_EQ(names(text), "mesh radiosity progress done ");
    EXPECT_NE(text.find("event: done\nid: 10\n"), std::string::npos) << text;
}

TEST(EventStream, RepeatedValuesComeWithoutTheirArraysToAClientThatHasThem) {
    EventStream stream;
    JobRecord job = running_job();
    EXPECT_EQ(names(stream.next(job, snapshot(1, 1, 1, 2, 10.0).get())), "mesh radiosity ");
    // The engine repeats the values of event 2: the arrays are not sent again.
    const json repeat =
        event_data(stream.next(job, snapshot(2, 1, 1, 3, 10.0, 2).get()), "radiosity");
    EXPECT_EQ(repeat["values_event"], 2);
    EXPECT_EQ(repeat["version"], 2);
    EXPECT_FALSE(repeat.contains("vertex_radiosity"));
    // A new client, or one resumed before event 2, gets them in full.
    EXPECT_TRUE(
        event_data(EventStream(0).next(job, snapshot(2, 1, 1, 3, 10.0, 2).get()), "radiosity")
            .contains("vertex_radiosity"));
    EXPECT_TRUE(
        event_data(EventStream(1).next(job, snapshot(2, 1, 1, 3, 10.0, 2).get()), "radiosity")
            .contains("vertex_radiosity"));
    EXPECT_FALSE(
        event_data(EventStream(2).next(job, snapshot(2, 1, 1, 3, 10.0, 2).get()), "radiosity")
            .contains("vertex_radiosity"));
    // The final event always carries its values.
    const json last =
        event_data(stream.next(job, snapshot(3, 1, 1, 4, 10.0, 2, true).get()), "radiosity");
    EXPECT_EQ(floats(last["vertex_radiosity"]), std::vector<float>({10, 10, 10}));
}

}  // namespace
