// Test helpers: IES LM-63 and EULUMDAT texts written from a known intensity function, so tests
// know every intensity the file holds.
#pragma once

#include <cmath>
#include <functional>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

namespace radiant::testing {

/// Intensity (cd) at γ, C in degrees.
using IntensityFunction = std::function<double(double gamma_deg, double c_deg)>;

inline std::vector<double> angles(double first, double last, double step) {
    std::vector<double> out;
    for (double a = first; a <= last + 1e-9; a += step) out.push_back(a);
    return out;
}

/// An LM-63-2002 file of photometric type C, TILT=NONE, values × 1 / `multiplier` so that the
/// multiplier restores them; `lumens` per lamp (−1: absolute photometry).
inline std::string ies_text(const std::vector<double>& gamma, const std::vector<double>& c,
                            const IntensityFunction& intensity, double lumens = -1,
                            double multiplier = 1) {
    std::ostringstream out;
    out.precision(12);
    out << "IESNA:LM-63-2002\n[TEST] written by the test\n[MANUFAC] Radiant\nTILT=NONE\n";
    out << "1 " << lumens << " " << multiplier << " " << gamma.size() << " " << c.size()
        << " 1 2 0.5 0.5 0\n1.0 1.0 40\n";
    for (const double g : gamma) out << g << " ";
    out << "\n";
    for (const double h : c) out << h << " ";
    out << "\n";
    for (const double h : c) {
        for (const double g : gamma) out << intensity(g, h) / multiplier << " ";
        out << "\n";
    }
    return out.str();
}

/// A EULUMDAT file with `mc` C-planes (step 360/mc), `gamma` angles, symmetry `isym`, one lamp
/// set of `lamp_flux` lm; intensities in cd/klm written with decimal commas.
inline std::string ldt_text(int isym, int mc, const std::vector<double>& gamma,
                            const IntensityFunction& intensity, double lamp_flux) {
    const auto comma = [](double x) {
        std::ostringstream s;
        s.precision(12);
        s << x;
        std::string t = s.str();
        for (char& ch : t) ch = ch == '.' ? ',' : ch;
        return t;
    };
    const double dc = 360.0 / mc;
    std::ostringstream out;
    out << "Radiant test\n1\n"
        << isym << "\n"
        << mc << "\n"
        << comma(dc) << "\n"
        << gamma.size() << "\n"
        << comma(gamma.size() > 1 ? gamma[1] - gamma[0] : 0) << "\nreport\nluminaire\n"
        << "number\ntest.ldt\n2026-11-23\n600\n600\n50\n580\n580\n0\n0\n0\n0\n100\n100\n1,0\n0\n"
        << "1\n1\nLED\n"
        << comma(lamp_flux) << "\n4000\n80\n40\n";
    for (int k = 0; k < 10; ++k) out << "0,5\n";
    for (int k = 0; k < mc; ++k) out << comma(k * dc) << "\n";
    for (const double g : gamma) out << comma(g) << "\n";
    int first = 0, count = mc;
    if (isym == 1) count = 1;
    if (isym == 2) count = mc / 2 + 1;
    if (isym == 3) first = 3 * mc / 4, count = mc / 2 + 1;
    if (isym == 4) count = mc / 4 + 1;
    for (int p = 0; p < count; ++p) {
        const double c = ((first + p) % mc) * dc;
        for (const double g : gamma) out << comma(intensity(g, c) * 1000 / lamp_flux) << "\n";
    }
    return out.str();
}

}  // namespace radiant::testing
