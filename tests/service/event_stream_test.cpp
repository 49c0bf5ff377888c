// What an event stream sends, without sockets: progress, mesh and radiosity events in one id
// sequence, each mesh once per version, Last-Event-ID resume, and done at the end.
#include "radiant/server/event_stream.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include <nlohmann/json.hpp>

namespace {

using namespace radiant::server;
using nlohmann::json;

JobRecord running_job() {
    JobRecord job;
    job.id = "abc";
    job.status = JobStatus::running;
    return job;
}

/// A one-triangle snapshot whose radiosity is `value`.
std::shared_ptr<const JobSnapshot> snapshot(std::uint64_t version, std::uint64_t mesh_version,
                                            std::uint64_t mesh_event_id,
                                            std::uint64_t radiosity_event_id, double value) {
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
    const std::string data = first.substr(first.find("data: ", first.find("event: radiosity")) + 6);
    const json radiosity = json::parse(data.substr(0, data.find('\n')));
    EXPECT_EQ(radiosity["mesh_version"], 1);
    EXPECT_EQ(radiosity["triangle_radiosity"], json::array({10.0}));
    EXPECT_EQ(radiosity["vertex_radiosity"].size(), 3u);

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

}  // namespace
