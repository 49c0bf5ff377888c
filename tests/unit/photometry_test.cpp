// IES LM-63 and EULUMDAT readers and the interpolated intensity table, on files written with
// known intensities.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "photometric_files.h"
#include "photometry/ies_reader.h"
#include "photometry/intensity_table.h"
#include "photometry/ldt_reader.h"

namespace radiant {
namespace {

using testing::angles;
using testing::ies_text;
using testing::ldt_text;

constexpr double kDeg = std::numbers::pi / 180;

/// A smooth, direction-dependent intensity: a cosine lobe, stronger along C0–C180.
double lobe(double gamma, double c) {
    return gamma > 90 ? 0 : 1000 * std::cos(gamma * kDeg) * (1 + 0.3 * std::cos(2 * c * kDeg));
}

PhotometricTable ies(const std::string& text) {
    auto parsed = proto::read_ies(text);
    if (auto* message = std::get_if<std::string>(&parsed)) ADD_FAILURE() << *message;
    return std::get<PhotometricTable>(parsed);
}

std::string ies_problem(const std::string& text) {
    auto parsed = proto::read_ies(text);
    return std::holds_alternative<std::string>(parsed) ? std::get<std::string>(parsed) : "";
}

PhotometricTable ldt(const std::string& text) {
    auto parsed = proto::read_ldt(text);
    if (auto* message = std::get_if<std::string>(&parsed)) ADD_FAILURE() << *message;
    return std::get<PhotometricTable>(parsed);
}

std::string ldt_problem(const std::string& text) {
    auto parsed = proto::read_ldt(text);
    return std::holds_alternative<std::string>(parsed) ? std::get<std::string>(parsed) : "";
}

struct SymmetryCase {
    const char* name;
    double c_first, c_last, c_step;
    testing::IntensityFunction intensity;  ///< has the symmetry the planes claim
};

class IesSymmetry : public ::testing::TestWithParam<SymmetryCase> {};

// Every plane the file leaves out shows the intensity of the plane it mirrors, and the table is
// exact at the file's own angles.
TEST_P(IesSymmetry, UnfoldsToAFullTurnAndIsExactAtTheNodes) {
    const SymmetryCase& k = GetParam();
    const auto gamma = angles(0, 180, 10);
    const auto c = angles(k.c_first, k.c_last, k.c_step);
    const PhotometricTable table = ies(ies_text(gamma, c, k.intensity));
    ASSERT_EQ(table.c_deg.size(), c.size());
    ASSERT_EQ(table.gamma_deg.size(), gamma.size());
    ASSERT_TRUE(photometric_table_problem(table).empty()) << photometric_table_problem(table);
    const IntensityTable t(table);
    for (double h = 0; h < 360; h += k.c_step) {
        for (const double g : gamma) {
            EXPECT_NEAR(t.candela(g * kDeg, h * kDeg), k.intensity(g, h), 1e-9 * 1000)
                << k.name << " gamma " << g << " C " << h;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(
    Planes, IesSymmetry,
    ::testing::Values(SymmetryCase{"rotational", 0, 0, 90,
                                   [](double g, double) { return 500 + 400 * std::cos(g * kDeg); }},
                      SymmetryCase{"quadrant", 0, 90, 15, lobe},
                      SymmetryCase{"plane_c0", 0, 180, 15,
                                   [](double g, double c) {
                                       return 600 + 200 * std::cos(g * kDeg) *
                                                        (1 + 0.5 * std::cos(c * kDeg));
                                   }},
                      SymmetryCase{"plane_c90", 90, 270, 15,
                                   [](double g, double c) {
                                       return 600 + 200 * std::cos(g * kDeg) *
                                                        (1 + 0.5 * std::sin(c * kDeg));
                                   }},
                      SymmetryCase{"none", 0, 345, 15,
                                   [](double g, double c) {
                                       return 600 + 200 * std::sin(g * kDeg) *
                                                        (1 + 0.5 * std::sin(c * kDeg) +
                                                         0.2 * std::cos(c * kDeg));
                                   }}),
    [](const auto& test_case) { return std::string(test_case.param.name); });

// LM-63-1995 and -1991 headers, the header-less 1986 layout and Windows line ends read alike.
TEST(IesReader, ReadsEveryHeaderVersion) {
    const auto gamma = angles(0, 90, 10);
    const std::string v2002 = ies_text(gamma, {0, 90}, lobe);
    const PhotometricTable want = ies(v2002);
    std::string crlf;
    for (const char ch : v2002) crlf += ch == '\n' ? std::string("\r\n") : std::string(1, ch);
    for (const std::string& text :
         {std::string("IESNA:LM-63-1995") + v2002.substr(v2002.find('\n')),
          std::string("IESNA91") + v2002.substr(v2002.find('\n')),
          v2002.substr(v2002.find("TILT=")), crlf}) {
        const PhotometricTable got = ies(text);
        EXPECT_EQ(got.gamma_deg, want.gamma_deg);
        EXPECT_EQ(got.c_deg, want.c_deg);
        EXPECT_EQ(got.candela, want.candela);
    }
}

TEST(IesReader, AppliesTheCandelaMultiplier) {
    const auto gamma = angles(0, 90, 10);
    const PhotometricTable table = ies(ies_text(gamma, {0}, lobe, 1000, 2.5));
    EXPECT_NEAR(table.at(0, 3), lobe(30, 0), 1e-9);
}

// Between the nodes the curve is smooth and never leaves the range of its neighbours (no
// overshoot below zero where intensity drops to nothing).
TEST(IntensityTable, StaysWithinNeighbouringValuesBetweenNodes) {
    const auto gamma = angles(0, 90, 10);
    // A sharp cut-off: full intensity to 40°, nothing beyond 50°.
    const auto cutoff = [](double g, double) { return g <= 40 ? 1000.0 : 0.0; };
    const IntensityTable t(ies(ies_text(gamma, {0}, cutoff)));
    for (double g = 0; g <= 90; g += 0.25) {
        const double i = t.candela(g * kDeg, 0);
        EXPECT_GE(i, 0) << g;
        EXPECT_LE(i, 1000 + 1e-9) << g;
    }
    EXPECT_GT(t.candela(45 * kDeg, 0), 0);
    EXPECT_LT(t.candela(45 * kDeg, 0), 1000);
    EXPECT_EQ(t.candela(120 * kDeg, 0), 0);  // the file covers the lower hemisphere only
}

// I = I0 cos γ below the horizon emits π I0; the file says so in its lumens.
TEST(IntensityTable, IntegratesToTheFilesLumens) {
    const double i0 = 1000;
    const double lumens = std::numbers::pi * i0;
    const auto gamma = angles(0, 90, 5);
    const auto lambert = [&](double g, double) { return i0 * std::cos(g * kDeg); };
    const IntensityTable t(ies(ies_text(gamma, {0}, lambert, lumens)));
    EXPECT_NEAR(t.flux_lm() / lumens, 1, 1e-3);
    // The lobe's C-variation averages out over a turn: it emits π·1000 lm too.
    const IntensityTable full(ies(ies_text(gamma, angles(0, 345, 15), lobe)));
    EXPECT_NEAR(full.flux_lm() / lumens, 1, 1e-3);
}

TEST(IesReader, RefusesMalformedFilesNamingTheLine) {
    const auto gamma = angles(0, 90, 5);
    const std::string good = ies_text(gamma, {0}, lobe);
    ASSERT_EQ(ies_problem(good), "");

    std::string short_list = good;
    // Claim 30 more vertical angles than listed: the horizontal angle 0 on line 8 ends the list.
    short_list.replace(short_list.find(" 19 1 1 2"), 9, " 49 1 1 2");
    EXPECT_EQ(ies_problem(short_list),
              "ies: line 8: expected 49 vertical angles, found 19 (0 does not increase)");

    std::string bad_number = good;
    bad_number.replace(bad_number.find("\n1.0 1.0 40"), 11, "\n1.0 1.0 4x0");
    EXPECT_EQ(ies_problem(bad_number), "ies: line 6: \"4x0\" is not a number");

    std::string tilt = good;
    tilt.replace(tilt.find("TILT=NONE"), 9, "TILT=INCLUDE");
    EXPECT_EQ(ies_problem(tilt), "ies: line 4: TILT=INCLUDE is not supported (only TILT=NONE)");

    std::string type_a = good;
    type_a.replace(type_a.find(" 1 2 0.5"), 8, " 3 2 0.5");
    EXPECT_EQ(ies_problem(type_a),
              "ies: line 5: photometric type A is not supported (only type C, 1)");
    std::string type_b = good;
    type_b.replace(type_b.find(" 1 2 0.5"), 8, " 2 2 0.5");
    EXPECT_EQ(ies_problem(type_b),
              "ies: line 5: photometric type B is not supported (only type C, 1)");

    const std::string truncated = good.substr(0, good.rfind(' ', good.size() - 3));
    EXPECT_EQ(ies_problem(truncated),
              "ies: line 9: expected 19 candela values at horizontal angle 0, found 18");

    std::string negative = good;
    negative.replace(negative.rfind("\n", negative.size() - 2) + 1, 4, "-5 ");
    EXPECT_EQ(ies_problem(negative), "ies: line 9: candela value -5 is negative");

    EXPECT_EQ(ies_problem("just some text\n"), "ies: no TILT= line: not an IES LM-63 file");
}

struct LdtCase {
    int isym;
    testing::IntensityFunction intensity;
};

class LdtSymmetry : public ::testing::TestWithParam<LdtCase> {};

// The same luminaire read from EULUMDAT gives the intensities of the function at every plane,
// whichever half or quarter the file stores.
TEST_P(LdtSymmetry, ReadsTheStoredPlanesInAbsoluteCandela) {
    const auto gamma = angles(0, 180, 10);
    const double lamp_flux = 2400;
    const PhotometricTable table =
        ldt(ldt_text(GetParam().isym, 24, gamma, GetParam().intensity, lamp_flux));
    ASSERT_TRUE(photometric_table_problem(table).empty()) << photometric_table_problem(table);
    const IntensityTable t(table);
    for (double c = 0; c < 360; c += 15) {
        for (const double g : gamma) {
            EXPECT_NEAR(t.candela(g * kDeg, c * kDeg), GetParam().intensity(g, c), 1e-6)
                << "Isym " << GetParam().isym << " gamma " << g << " C " << c;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(
    Isym, LdtSymmetry,
    ::testing::Values(
        LdtCase{0, [](double g,
                      double c) { return 300 + 100 * std::sin(g * kDeg) * std::sin(c * kDeg); }},
        LdtCase{1, [](double g, double) { return 300 + 100 * std::cos(g * kDeg); }},
        LdtCase{2, [](double g,
                      double c) { return 300 + 100 * std::sin(g * kDeg) * std::cos(c * kDeg); }},
        LdtCase{3, [](double g,
                      double c) { return 300 + 100 * std::sin(g * kDeg) * std::sin(c * kDeg); }},
        LdtCase{4, lobe}),
    [](const auto& test_case) { return "isym" + std::to_string(test_case.param.isym); });

TEST(LdtReader, RefusesMalformedFilesNamingTheLine) {
    const auto gamma = angles(0, 90, 10);
    const std::string good = ldt_text(4, 24, gamma, lobe, 1000);
    ASSERT_EQ(ldt_problem(good), "");
    std::string bad_symmetry = good;
    bad_symmetry.replace(bad_symmetry.find("\n4\n"), 3, "\n7\n");
    EXPECT_EQ(ldt_problem(bad_symmetry),
              "ldt: line 3: symmetry indicator Isym must be a whole number in 0–4");
    std::string bad_number = good;
    bad_number.replace(bad_number.find("\nLED\n1000\n"), 10, "\nLED\n1OOO\n");
    EXPECT_EQ(ldt_problem(bad_number),
              "ldt: line 29: total luminous flux of lamps: \"1OOO\" is not a number");
    // 7 planes (Isym 4 of 24) × 10 angles from line 77 on; drop the last three.
    std::string truncated = good;
    for (int k = 0; k < 3; ++k) truncated.erase(truncated.rfind('\n', truncated.size() - 2) + 1);
    EXPECT_EQ(ldt_problem(truncated), "ldt: line 143: expected 70 luminous intensities, found 67");
}

}  // namespace
}  // namespace radiant
