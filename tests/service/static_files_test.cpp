// The web viewer's static files: content types, HEAD, and that nothing outside the web root is
// ever served — by the path rules, through the router, and over a real socket to radiantd.
#include "radiant/server/static_files.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "daemon.h"
#include "radiant/server/config.h"
#include "radiant/server/router.h"
#include "store_under_test.h"

namespace {

namespace fs = std::filesystem;
using namespace radiant::server;
using nlohmann::json;

void write(const fs::path& file, const std::string& text) {
    fs::create_directories(file.parent_path());
    std::ofstream(file, std::ios::binary) << text;
}

/// A web root with a few files, and a secret beside it that must never be served.
class WebRoot : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("radiant_static_test_" + std::to_string(getpid()) +
                                            "_" + radiant::test::test_file_name());
        fs::remove_all(dir_);
        root_ = dir_ / "web";
        write(root_ / "index.html", "<!doctype html><title>viewer</title>");
        write(root_ / "assets" / "app.js", "export const x = 1;\n");
        write(root_ / "assets" / "style.css", "body{}");
        write(root_ / "examples" / "index.json", "[]");
        write(root_ / "examples" / "room" / "lamp.ies", "IESNA:LM-63-2002\n");
        write(root_ / "examples" / "index.html", "<p>examples</p>");
        write(root_ / ".hidden", "dotfile");
        write(root_ / "data.bin", "\x01\x02");
        write(dir_ / "secret.txt", "SECRET");
        fs::create_symlink(dir_ / "secret.txt", root_ / "leak.txt");
        fs::create_symlink(root_ / "assets" / "app.js", root_ / "alias.js");
    }
    void TearDown() override { fs::remove_all(dir_); }

    Response get(const std::string& target, http::verb method = http::verb::get) {
        Request request{method, target, 11};
        request.prepare_payload();
        return StaticFiles(root_).serve(request, target);
    }

    fs::path dir_, root_;
};

TEST(StaticFilePath, NamesFilesUnderTheRootOnly) {
    const fs::path root = "/srv/web";
    EXPECT_EQ(static_file_path(root, "/"), root / "index.html");
    EXPECT_EQ(static_file_path(root, ""), root / "index.html");
    EXPECT_EQ(static_file_path(root, "/assets/app.js"), root / "assets/app.js");
    EXPECT_EQ(static_file_path(root, "//assets//app.js"), root / "assets/app.js");
    EXPECT_EQ(static_file_path(root, "/examples/"), root / "examples/index.html");
    EXPECT_EQ(static_file_path(root, "/a%20b.json"), root / "a b.json");
    EXPECT_EQ(static_file_path(root, "/a+b.json"), root / "a+b.json");  // '+' is no space here
    for (const char* bad :
         {"/..", "/../secret.txt", "/assets/../../secret.txt", "/%2e%2e/secret.txt",
          "/%2E%2E%2Fsecret.txt", "/assets/..%2f..%2fsecret.txt", "/.", "/./index.html", "/.hidden",
          "/.git/config", "/a%5c..%5csecret.txt", "/a\\b", "/a%00.js"}) {
        EXPECT_EQ(static_file_path(root, bad), std::nullopt) << bad;
    }
}

TEST(StaticFilePath, ContentTypesByExtension) {
    EXPECT_STREQ(static_content_type("index.html"), "text/html; charset=utf-8");
    EXPECT_STREQ(static_content_type("a/app-1f2e.js"), "text/javascript; charset=utf-8");
    EXPECT_STREQ(static_content_type("style.css"), "text/css; charset=utf-8");
    EXPECT_STREQ(static_content_type("index.json"), "application/json");
    EXPECT_STREQ(static_content_type("lamp.ies"), "text/plain; charset=utf-8");
    EXPECT_STREQ(static_content_type("chair.obj"), "text/plain; charset=utf-8");
    EXPECT_STREQ(static_content_type("icon.svg"), "image/svg+xml");
    EXPECT_STREQ(static_content_type("README"), "application/octet-stream");
    EXPECT_STREQ(static_content_type("x.exe"), "application/octet-stream");
}

TEST(StaticFilePath, DefaultRootIsBesideTheBinary) {
    EXPECT_EQ(default_web_root("/usr/local/bin/radiantd"), "/usr/local/share/radiant/web");
    EXPECT_EQ(default_web_root("/work/build/bin/radiantd"), "/work/build/share/radiant/web");
}

TEST_F(WebRoot, ServesFilesWithTheirTypes) {
    EXPECT_TRUE(StaticFiles(root_).installed());
    Response index = get("/");
    EXPECT_EQ(index.result(), http::status::ok);
    EXPECT_EQ(index.body(), "<!doctype html><title>viewer</title>");
    EXPECT_EQ(index[http::field::content_type], "text/html; charset=utf-8");
    EXPECT_EQ(index["X-Content-Type-Options"], "nosniff");
    EXPECT_NE(index["Content-Security-Policy"].find("default-src 'self'"), std::string::npos);

    EXPECT_EQ(get("/assets/app.js")[http::field::content_type], "text/javascript; charset=utf-8");
    EXPECT_EQ(get("/assets/style.css")[http::field::content_type], "text/css; charset=utf-8");
    EXPECT_EQ(get("/examples/room/lamp.ies").body(), "IESNA:LM-63-2002\n");
    EXPECT_EQ(get("/examples/").body(), "<p>examples</p>");
    EXPECT_EQ(get("/data.bin")[http::field::content_type], "application/octet-stream");
    // A link that stays inside the root is followed.
    EXPECT_EQ(get("/alias.js").body(), "export const x = 1;\n");
}

TEST_F(WebRoot, HeadHasTheLengthButNoBody) {
    Response head = get("/assets/app.js", http::verb::head);
    EXPECT_EQ(head.result(), http::status::ok);
    EXPECT_EQ(head.body(), "");
    EXPECT_EQ(head[http::field::content_length], "20");
}

TEST_F(WebRoot, NothingOutsideTheRootNorHidden) {
    for (const char* target : {"/../secret.txt", "/%2e%2e/secret.txt", "/leak.txt", "/.hidden",
                               "/assets", "/missing.js", "/assets/app.js/x"}) {
        Response r = get(target);
        EXPECT_EQ(r.result(), http::status::not_found) << target;
        EXPECT_EQ(r.body().find("SECRET"), std::string::npos) << target;
        EXPECT_EQ(json::parse(r.body())["error"]["code"], "not_found") << target;
    }
}

TEST_F(WebRoot, WithoutAViewerEveryPathIs404) {
    EXPECT_FALSE(StaticFiles().installed());
    EXPECT_FALSE(StaticFiles(dir_ / "nowhere").installed());
    Request request{http::verb::get, "/", 11};
    EXPECT_EQ(StaticFiles().serve(request, "/").result(), http::status::not_found);
    EXPECT_EQ(StaticFiles(dir_ / "nowhere").serve(request, "/").result(), http::status::not_found);
}

/// radiantd itself, on each store.
class WebRootDaemon : public WebRoot, public ::testing::WithParamInterface<std::string> {
protected:
    void SetUp() override {
        const std::string skip = radiant::test::StoreUnderTest::skip_reason(GetParam());
        if (!skip.empty()) GTEST_SKIP() << skip;
        WebRoot::SetUp();
        store_.emplace(GetParam());
    }
    std::optional<radiant::test::StoreUnderTest> store_;
};
INSTANTIATE_TEST_SUITE_P(Stores, WebRootDaemon, radiant::test::both_stores(),
                         radiant::test::store_name);

/// The raw request targets go through Beast's parser and the router untouched.
TEST_P(WebRootDaemon, TheDaemonServesTheViewerAndNothingElse) {
    using boost::beast::http::verb;
    using radiant::test::http_call;
    radiant::test::Daemon d(dir_ / "data", store_->daemon_flags({"--web-root", root_.string()}),
                            dir_ / "radiantd.log");
    const auto index = http_call(d.port(), verb::get, "/");
    EXPECT_EQ(index.status, 200u);
    EXPECT_EQ(index.headers.at("Content-Type"), "text/html; charset=utf-8");
    EXPECT_EQ(index.body, "<!doctype html><title>viewer</title>");
    EXPECT_EQ(http_call(d.port(), verb::get, "/assets/app.js?v=2").body, "export const x = 1;\n");
    for (const char* target : {"/../secret.txt", "/assets/../../secret.txt", "/%2e%2e/secret.txt",
                               "/..%2fsecret.txt", "/leak.txt", "/.hidden"}) {
        const auto r = http_call(d.port(), verb::get, target);
        EXPECT_EQ(r.status, 404u) << target;
        EXPECT_EQ(r.body.find("SECRET"), std::string::npos) << target;
    }
    EXPECT_EQ(http_call(d.port(), verb::post, "/", "{}").status, 405u);
    EXPECT_EQ(http_call(d.port(), verb::delete_, "/index.html").status, 405u);
    // The API keeps its own answers: /v1 paths are never files.
    EXPECT_EQ(http_call(d.port(), verb::get, "/v1/index.html").status, 404u);
    EXPECT_EQ(http_call(d.port(), verb::get, "/healthz").status, 200u);
    EXPECT_EQ(http_call(d.port(), verb::get, "/v1/jobs").status, 200u);
}

}  // namespace
