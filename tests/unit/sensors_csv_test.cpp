// Sensor points as CSV (`radiant solve --csv`): read back by Python's csv module — the reader a
// spreadsheet import is modelled on — the rows carry the JSON result's points, normals and lux.
#include "radiant/proto/sensors_csv.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_run.h"
#include "test_files.h"

namespace radiant::proto {
namespace {

namespace fs = std::filesystem;

struct Scratch {
    fs::path dir = fs::temp_directory_path() / ("radiant_csv_test_" + std::to_string(getpid()));
    Scratch() { fs::create_directories(dir); }
    ~Scratch() { fs::remove_all(dir); }
};

/// The rows of a CSV file as Python's csv module reads them (RFC 4180 dialect "excel").
std::vector<std::vector<std::string>> python_csv_rows(const fs::path& file) {
    const std::string command =
        "python3 -c 'import csv, json, sys; "
        "print(json.dumps(list(csv.reader(open(sys.argv[1], newline=\"\")))))' '" +
        file.string() + "'";
    FILE* pipe = popen(command.c_str(), "r");
    std::string text;
    char buffer[4096];
    while (pipe && std::fgets(buffer, sizeof buffer, pipe)) text += buffer;
    EXPECT_TRUE(pipe && pclose(pipe) == 0) << command;
    return nlohmann::json::parse(text).get<std::vector<std::vector<std::string>>>();
}

TEST(SensorsCsv, QuotesNamesAndEndsLinesInCrLf) {
    SensorResult set;
    set.name = "desk, \"north\"";
    set.points = {{1.0000001, 2, 3}};
    set.normal = {0, 0, 1};
    set.illuminance = {512.345};
    const std::string csv = sensors_csv({set});
    EXPECT_EQ(csv,
              "set,index,x,y,z,nx,ny,nz,lux\r\n"
              "\"desk, \"\"north\"\"\",0,1,2,3,0,0,1,512.3\r\n");
    Scratch scratch;
    const fs::path file = scratch.dir / "one.csv";
    std::ofstream(file, std::ios::binary) << csv;
    const auto rows = python_csv_rows(file);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[1][0], "desk, \"north\"");
    EXPECT_EQ(rows[1][8], "512.3");
}

/// A 4 × 4 × 3 m room in millimetres with a 3 × 2 grid and two named points.
std::string room_scene() {
    return R"({"format": "radiant-scene/1", "name": "csv-room", "units": "mm",
  "materials": {"wall": {"reflectance": 0.5}},
  "surfaces": [{"name": "room", "material": "wall",
                "box": {"min": [0, 0, 0], "max": [4000, 4000, 3000], "facing": "in"}}],
  "luminaires": [{"name": "bulb", "position": [2000, 2000, 2500], "flux": 1000}],
  "sensors": [
    {"name": "grid", "normal": [0, 0, 2],
     "grid": {"origin": [500, 1000, 800], "u": [3000, 0, 0], "v": [0, 2000, 0], "nu": 3, "nv": 2}},
    {"name": "desk, \"north\"", "normal": [0, -1, 0], "points": [[1200, 3000, 750], [2800, 3000, 750]]}
  ],
  "settings": {"tolerance": 0.1}})";
}

TEST(SensorsCsv, SolveWritesEveryPointWithTheResultsNumbers) {
    Scratch scratch;
    const fs::path scene = scratch.dir / "room.json";
    std::ofstream(scene) << room_scene();
    for (const int digits : {4, 17}) {
        SCOPED_TRACE(digits);
        const fs::path out = scratch.dir / "result.json", csv = scratch.dir / "points.csv";
        const test::CliRun r =
            test::run_cli("solve '" + scene.string() + "' --out '" + out.string() + "' --csv '" +
                          csv.string() + "' --digits " + std::to_string(digits));
        ASSERT_EQ(r.exit_code, 0) << r.err;
        const auto result = nlohmann::json::parse(test::read_text(out));
        const auto& sets = result["sensors"];
        ASSERT_EQ(sets.size(), 2u);
        // Grid points in metres, u fastest; the normal made a unit vector.
        EXPECT_EQ(sets[0]["points"][1], nlohmann::json({2.0, 1.5, 0.8}));
        EXPECT_EQ(sets[0]["points"][3], nlohmann::json({1.0, 2.5, 0.8}));
        EXPECT_EQ(sets[0]["normal"], nlohmann::json({0.0, 0.0, 1.0}));
        EXPECT_EQ(sets[1]["points"][0], nlohmann::json({1.2, 3.0, 0.75}));

        const auto rows = python_csv_rows(csv);
        ASSERT_EQ(rows.size(), 1u + 6 + 2);
        EXPECT_EQ(rows[0], (std::vector<std::string>{"set", "index", "x", "y", "z", "nx", "ny",
                                                     "nz", "lux"}));
        std::size_t row = 1;
        for (const auto& set : sets) {
            for (std::size_t i = 0; i < set["points"].size(); ++i, ++row) {
                const auto& cells = rows[row];
                ASSERT_EQ(cells.size(), 9u);
                EXPECT_EQ(cells[0], set["name"].get<std::string>());
                EXPECT_EQ(cells[1], std::to_string(i));
                for (int k = 0; k < 3; ++k) {
                    EXPECT_EQ(std::stod(cells[2 + k]), set["points"][i][k].get<double>());
                    EXPECT_EQ(std::stod(cells[5 + k]), set["normal"][k].get<double>());
                }
                EXPECT_EQ(std::stod(cells[8]), set["illuminance"][i].get<double>());
                EXPECT_GT(std::stod(cells[8]), 0);
            }
        }
    }
}

}  // namespace
}  // namespace radiant::proto
