// kinematics.cpp - MoorDyn's WaveKin and Currents options (docs/lines.md, "Options and environment"): what
// the FMU's sea state holds is read into it from the companion files next to the deck (current_profile.txt,
// wave_frequencies.txt, wave_elevation.txt), the rest refused naming the option, its value and why; and the
// FMU's own file of wave components (waves.file).
#include "deck/tables.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdio>

#include <Eigen/Dense>

#include "core/types.h"

namespace uc {
namespace deck {
namespace {

const char* kCurrentProfileFile = "current_profile.txt";
const char* kWaveFrequenciesFile = "wave_frequencies.txt";
const char* kWaveElevationFile = "wave_elevation.txt";
const char* kCurrentDynamicFile = "current_profile_dynamic.txt";
const char* kCurrent4dFile = "current_profile_4d.txt";

const LineFileCompanion* companion(const LineFileCompanions& companions, const char* name) {
    for (const LineFileCompanion& c : companions) {
        if (c.name == name) return &c;
    }
    return nullptr;
}

// The rows of numbers of a companion file from its line `first` (1-based), blank lines skipped.
struct NumberRow {
    int number = 0;
    std::vector<double> values;
};

bool number_rows(const LineFileCompanion& file, int first, std::vector<NumberRow>& rows, std::string& what) {
    const std::vector<std::string_view> lines = split_lines(file.text);
    for (size_t i = static_cast<size_t>(first - 1); i < lines.size(); ++i) {
        NumberRow row{static_cast<int>(i) + 1, {}};
        for (std::string_view token : tokenize(lines[i])) {
            const std::optional<double> v = to_number(token);
            if (!v) {
                what = file.name + " line " + std::to_string(row.number) + ": " + quoted(token) + " is not a number";
                return false;
            }
            row.values.push_back(*v);
        }
        if (!row.values.empty()) rows.push_back(row);
    }
    return true;
}

// Drops the rows of a piecewise-linear profile (depth increasing) that the others give by MoorDyn's
// interpolation (linear between rows, constant beyond the ends) to round-off of the largest speed.
void drop_redundant_rows(std::vector<std::array<double, 3>>& rows) {
    double scale = 0.0;
    for (const auto& r : rows) scale = std::max({scale, std::abs(r[1]), std::abs(r[2])});
    const double tol = 1e-9 * std::max(scale, 1e-300);
    auto same = [&](const std::array<double, 3>& a, const std::array<double, 3>& b) {
        return std::abs(a[1] - b[1]) <= tol && std::abs(a[2] - b[2]) <= tol;
    };
    while (rows.size() > 1 && same(rows[rows.size() - 1], rows[rows.size() - 2])) rows.pop_back();
    while (rows.size() > 1 && same(rows[0], rows[1])) rows.erase(rows.begin());
    std::vector<std::array<double, 3>> kept{rows.front()};
    for (size_t i = 1; i + 1 < rows.size(); ++i) {
        // row i may go when every row from the last kept one to row i + 1 lies on their chord
        const auto& a = kept.back();
        const auto& b = rows[i + 1];
        bool onChord = true;
        for (size_t j = 0; j <= i && onChord; ++j) {
            const auto& r = rows[j];
            if (r[0] <= a[0]) continue;
            const double f = (r[0] - a[0]) / (b[0] - a[0]);
            std::array<double, 3> line{r[0], a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])};
            onChord = same(r, line);
        }
        if (!onChord) kept.push_back(rows[i]);
    }
    if (rows.size() > 1) kept.push_back(rows.back());
    rows = kept;
}

// Currents 1: MoorDyn's steady profile, rows "z ux [uy [uz]]" from the file's fourth line, z increasing,
// linear in z between rows and constant beyond; as the FMU's profile of depths -z.
bool read_current_profile(const LineFileCompanion& file, LineFileSea& sea, std::string& what) {
    std::vector<NumberRow> rows;
    if (!number_rows(file, 4, rows, what)) return false;
    if (rows.empty()) {
        what = file.name + " has no rows of the profile (\"z ux uy uz\" from its fourth line)";
        return false;
    }
    std::vector<std::array<double, 3>> profile;  // depth, ux, uy; depth increasing
    for (size_t i = 0; i < rows.size(); ++i) {
        const NumberRow& r = rows[i];
        const std::string at = file.name + " line " + std::to_string(r.number) + ": ";
        if (r.values.size() < 2 || r.values.size() > 4) {
            what = at + "a row is z ux [uy [uz]]";
            return false;
        }
        if (r.values.size() == 4 && r.values[3] != 0.0) {
            what = at + "uz = " + number_text(r.values[3]) + ": a vertical current is not supported (the FMU's "
                        "current is horizontal)";
            return false;
        }
        if (i > 0 && !(r.values[0] > rows[i - 1].values[0])) {
            what = at + "z = " + number_text(r.values[0]) + ": z must increase row by row (MoorDyn interpolates "
                        "between rows in that order)";
            return false;
        }
        profile.insert(profile.begin(), {-r.values[0], r.values[1], r.values.size() > 2 ? r.values[2] : 0.0});
    }
    const size_t given = profile.size();
    drop_redundant_rows(profile);
    if (profile.size() > UC_CURRENT_PROFILE_ROWS) {
        what = file.name + ": a profile of " + std::to_string(given) + " rows, " + std::to_string(profile.size()) +
               " of them off the straight lines between their neighbours: the FMU's current profile "
               "(currentProfile.*) holds " + std::to_string(UC_CURRENT_PROFILE_ROWS) + " rows";
        return false;
    }
    sea.profileRows = static_cast<int>(profile.size());
    for (size_t k = 0; k < profile.size(); ++k) {
        sea.profileDepth[k] = profile[k][0];
        sea.profileX[k] = profile[k][1];
        sea.profileY[k] = profile[k][2];
    }
    return true;
}

// The rows "omega Re(A) Im(A) [direction]" of MoorDyn's wave_frequencies.txt (blank rows skipped).
struct SpectrumRow {
    double omega;
    std::complex<double> A;
    double direction;
    int row;
};

bool spectrum_rows(const LineFileCompanion& file, std::vector<SpectrumRow>& out, std::string& what) {
    std::vector<NumberRow> rows;
    if (!number_rows(file, 1, rows, what)) return false;
    for (const NumberRow& r : rows) {
        if (r.values.size() < 3 || r.values.size() > 4) {
            what = file.name + " line " + std::to_string(r.number) + ": a row is omega Re(A) Im(A) [direction]";
            return false;
        }
        out.push_back({r.values[0], {r.values[1], r.values[2]}, r.values.size() > 3 ? r.values[3] : 0.0, r.number});
    }
    return true;
}

// WaveKin 7: MoorDyn sums the components "omega Re(A) Im(A) [direction]" of the file, each the elevation
// |A| sin(omega t - k x + arg A) (x along the direction) = |A| cos(k x - omega t + pi/2 - arg A): the given
// components of waves.mode 3, amplitude |A|, phase pi/2 - arg A. One component with arg A = pi/2 is the
// FMU's regular wave of amplitude |A|, a cos(k x - omega t), crest at the origin at t = 0 (waves.mode 1).
bool read_wave_components(const LineFileCompanion& file, LineFileSea& sea, std::string& what) {
    std::vector<SpectrumRow> rows;
    if (!spectrum_rows(file, rows, what)) return false;
    std::vector<const SpectrumRow*> waves;
    for (const SpectrumRow& r : rows) {
        if (r.A == 0.0) continue;
        if (!(r.omega > 0.0)) {
            what = file.name + " line " + std::to_string(r.row) + ": a component of frequency " + number_text(r.omega) +
                   " rad/s is not a wave";
            return false;
        }
        waves.push_back(&r);
    }
    if (waves.empty()) return true;  // still water
    const SpectrumRow& w = *waves[0];
    const double amplitude = std::abs(w.A);
    if (waves.size() == 1 && w.A.imag() > 0.0 && std::abs(w.A.real()) <= 1e-12 * amplitude) {
        sea.regularWave = true;
        sea.waveHeight = 2.0 * amplitude;
        sea.wavePeriod = 2.0 * kPi / w.omega;
        sea.waveDirection = w.direction;
        return true;
    }
    for (const SpectrumRow* c : waves) sea.waveComponents.push_back({c->omega, std::abs(c->A), 0.5 * kPi - std::arg(c->A), c->direction});
    return true;
}

// WaveKin 2: MoorDyn interpolates the spectrum linearly to frequencies i dw (dw the smallest spacing of
// the file, from 0 to its last frequency) and transforms them on its grid into the elevation
// Re(A e^{i (omega t - k x)}) = |A| cos(k x - omega t - arg A) (its inverse FFT, scaled by (N - 1) / nt);
// the last frequency, the transform's Nyquist bin, enters as Re(A) / 2. Those interpolated components,
// summed at every point (no grid), are the given components of waves.mode 3.
bool read_wave_spectrum(const LineFileCompanion& file, LineFileSea& sea, std::string& what,
                        std::vector<std::string>& notes, int row) {
    std::vector<SpectrumRow> rows;
    if (!spectrum_rows(file, rows, what)) return false;
    if (rows.size() < 2 || rows[0].omega != 0.0) {
        what = file.name + ": MoorDyn's spectrum has at least two rows, the first at 0 rad/s";
        return false;
    }
    double dw = HUGE_VAL;
    for (size_t i = 1; i < rows.size(); ++i) {
        const double d = rows[i].omega - rows[i - 1].omega;
        if (!(d > 0.0)) {
            what = file.name + " line " + std::to_string(rows[i].row) + ": omega = " + number_text(rows[i].omega) +
                   " rad/s: the frequencies must increase row by row (MoorDyn interpolates between them)";
            return false;
        }
        dw = std::min(dw, d);
    }
    const size_t n = static_cast<size_t>(std::floor(rows.back().omega / dw)) + 1;
    if (n > 100 * static_cast<size_t>(UC_MAX_WAVE_COMPONENTS)) {
        what = file.name + ": " + std::to_string(n) + " frequencies of spacing " + number_text(dw) +
               " rad/s (the smallest of the file) up to " + number_text(rows.back().omega) + " rad/s";
        return false;
    }
    size_t j = 1;
    for (size_t i = 0; i < n; ++i) {
        const double w = static_cast<double>(i) * dw;
        while (j + 1 < rows.size() && rows[j].omega < w) ++j;
        const double f = std::clamp((w - rows[j - 1].omega) / (rows[j].omega - rows[j - 1].omega), 0.0, 1.0);
        std::complex<double> A = rows[j - 1].A + f * (rows[j].A - rows[j - 1].A);
        const double direction = rows[j - 1].direction + f * (rows[j].direction - rows[j - 1].direction);
        if (i == 0) {
            if (A != 0.0) {
                notes.push_back(at_line(row, "WaveKin 2: the component at 0 rad/s of wave_frequencies.txt, a mean level of " +
                                                 number_text(0.5 * A.real()) + " m in MoorDyn's transform, is not a wave: left out"));
            }
            continue;
        }
        if (i + 1 == n && n > 1) A = 0.5 * A.real();  // the Nyquist bin
        if (A == 0.0) continue;
        sea.waveComponents.push_back({w, std::abs(A), -std::arg(A), direction});
    }
    return true;
}

// The samples of a record (t, value) resampled at t = i dt, i = 0 .. n - 1, linear between samples and
// constant beyond its ends (MoorDyn's interpolation).
std::vector<double> resample(const std::vector<std::array<double, 2>>& record, double dt, size_t n) {
    std::vector<double> out(n);
    size_t j = 1;
    for (size_t i = 0; i < n; ++i) {
        const double t = static_cast<double>(i) * dt;
        while (j + 1 < record.size() && record[j][0] < t) ++j;
        const auto& a = record[j - 1];
        const auto& b = record[j];
        const double f = std::clamp((t - a[0]) / (b[0] - a[0]), 0.0, 1.0);
        out[i] = a[1] + f * (b[1] - a[1]);
    }
    return out;
}

// WaveKin 3: MoorDyn resamples the record of wave_elevation.txt ("t elevation" rows) at dtWave, drops the
// last sample of an odd count, and takes its discrete Fourier transform X_j (j = 0 .. nt / 2, frequencies
// j dw, dw = 2 pi / (nt dtWave)), cutting the frequencies above 0.5 Hz: the elevation is the sum of
// (2 / nt) Re(X_j e^{i (omega t - k x)}) (the Nyquist bin counted once), travelling along +x. The same
// components (amplitude 2 |X_j| / nt, phase -arg X_j; the mean X_0 / nt left out, noted) are the given
// components of waves.mode 3: their sum is the resampled record at its sample times.
bool read_wave_record(const LineFileCompanion& file, double dtWave, LineFileSea& sea, std::string& what,
                      std::vector<std::string>& notes, int row) {
    std::vector<NumberRow> rows;
    if (!number_rows(file, 1, rows, what)) return false;
    std::vector<std::array<double, 2>> record;
    for (const NumberRow& r : rows) {
        const std::string at = file.name + " line " + std::to_string(r.number) + ": ";
        if (r.values.size() != 2) {
            what = at + "a row is t elevation";
            return false;
        }
        if (!record.empty() && !(r.values[0] > record.back()[0])) {
            what = at + "t = " + number_text(r.values[0]) + " s: the times must increase row by row";
            return false;
        }
        record.push_back({r.values[0], r.values[1]});
    }
    if (record.size() < 2 || !(record.back()[0] >= 2.0 * dtWave)) {
        what = file.name + ": a record of " + std::to_string(record.size()) + " rows up to t = " +
               number_text(record.empty() ? 0.0 : record.back()[0]) + " s is shorter than two steps of dtWave = " +
               number_text(dtWave) + " s";
        return false;
    }
    size_t nt = static_cast<size_t>(std::floor(record.back()[0] / dtWave)) + 1;
    nt -= nt % 2;
    const std::vector<double> x = resample(record, dtWave, nt);
    const double dw = 2.0 * kPi / (static_cast<double>(nt) * dtWave);
    const size_t last = std::min(nt / 2, static_cast<size_t>(std::floor(kPi / dw)));  // 0.5 Hz
    if (last > static_cast<size_t>(UC_MAX_WAVE_COMPONENTS)) {
        what = file.name + ": " + std::to_string(last) + " frequencies up to 0.5 Hz in a record of " +
               number_text(static_cast<double>(nt) * dtWave) + " s, the FMU holds " +
               std::to_string(UC_MAX_WAVE_COMPONENTS) + " components (a record of at most " +
               number_text(2.0 * UC_MAX_WAVE_COMPONENTS) + " s)";
        return false;
    }
    double mean = 0.0;
    for (double v : x) mean += v;
    mean /= static_cast<double>(nt);
    // X_j = sum_m x_m e^{-2 pi i j m / nt}, the angle's multiple reduced modulo nt exactly
    for (size_t j = 1; j <= last; ++j) {
        std::complex<double> X = 0.0;
        for (size_t m = 0; m < nt; ++m) {
            const double angle = -2.0 * kPi * static_cast<double>((j * m) % nt) / static_cast<double>(nt);
            X += x[m] * std::complex<double>(std::cos(angle), std::sin(angle));
        }
        const double scale = j == nt / 2 ? 1.0 / static_cast<double>(nt) : 2.0 / static_cast<double>(nt);
        if (j == nt / 2) X = X.real();  // the Nyquist bin: a real cosine at the samples
        if (X == 0.0) continue;
        sea.waveComponents.push_back({static_cast<double>(j) * dw, scale * std::abs(X), -std::arg(X), 0.0});
    }
    char meanText[32];
    std::snprintf(meanText, sizeof meanText, "%.6g", mean);
    notes.push_back(at_line(row, "WaveKin 3: the record of wave_elevation.txt resampled at dtWave = " + number_text(dtWave) +
                                     " s (" + std::to_string(nt) + " samples) is the sum of its " +
                                     std::to_string(sea.waveComponents.size()) + " Fourier components up to 0.5 Hz, "
                                     "as MoorDyn transforms it; its mean " + std::string(meanText) + " m is not a wave: left out"));
    return true;
}

}  // namespace

// The deck's kinematics options into the FMU's sea state, or the refusal naming the option and why.
bool read_sea(const Options& options, const LineFileCompanions& companions, LineFileSea& sea,
              std::vector<std::string>& notes, std::string& error) {
    const auto [waveKin, waveRow] = options.waveKin;
    const auto [currents, currentRow] = options.currents;
    auto refuse = [&](int row, const char* name, int value, const std::string& why) {
        error = at_line(row, std::string(name) + " = " + std::to_string(value) + ": " + why);
        return false;
    };
    auto file = [&](int row, const char* name, int value, const char* fileName, const LineFileCompanion*& out) {
        out = companion(companions, fileName);
        if (out) return true;
        return refuse(row, name, value, std::string("MoorDyn reads ") + fileName + " from the deck's directory: "
                                                    "it could not be read there");
    };
    const LineFileCompanion* text = nullptr;
    std::string what;
    switch (waveKin) {
        case 0: break;
        case 1:
            notes.push_back(at_line(waveRow, "WaveKin 1 (water kinematics set by the program driving MoorDyn): the "
                                             "water moves as the FMU's sea state, waves.* and current.*, set by the "
                                             "importer"));
            break;
        case 2:
            if (!file(waveRow, "WaveKin", waveKin, kWaveFrequenciesFile, text)) return false;
            if (!read_wave_spectrum(*text, sea, what, notes, waveRow)) return refuse(waveRow, "WaveKin", waveKin, what);
            notes.push_back(at_line(waveRow, "WaveKin 2: the spectrum of wave_frequencies.txt, interpolated to equal "
                                             "frequency steps as MoorDyn does, is " + std::to_string(sea.waveComponents.size()) +
                                             " given components (waves.mode 3, Wheeler stretching, in place of the parameters "
                                             "waves.*), summed at every point: water_grid.txt, MoorDyn's grid, is not read"));
            break;
        case 3:
            if (!file(waveRow, "WaveKin", waveKin, kWaveElevationFile, text)) return false;
            if (!read_wave_record(*text, options.dtWave, sea, what, notes, waveRow))
                return refuse(waveRow, "WaveKin", waveKin, what);
            break;
        case 4: case 5: case 6:
            return refuse(waveRow, "WaveKin", waveKin, "not implemented in MoorDyn v2 either");
        case 7:
            if (!file(waveRow, "WaveKin", waveKin, kWaveFrequenciesFile, text)) return false;
            if (!read_wave_components(*text, sea, what)) return refuse(waveRow, "WaveKin", waveKin, what);
            if (sea.regularWave) {
                notes.push_back(at_line(waveRow, "WaveKin 7: the one component of wave_frequencies.txt is the regular "
                                                 "wave waves.mode 1, height " + number_text(sea.waveHeight) + " m, period " +
                                                 number_text(sea.wavePeriod) + " s, direction " +
                                                 number_text(sea.waveDirection) + " rad, Wheeler stretching (in place of "
                                                 "the parameters waves.*)"));
            } else {
                notes.push_back(at_line(waveRow, "WaveKin 7: the " + std::to_string(sea.waveComponents.size()) +
                                                 " components of wave_frequencies.txt are the given components of "
                                                 "waves.mode 3, Wheeler stretching (in place of the parameters waves.*)"));
            }
            break;
        default:
            return refuse(waveRow, "WaveKin", waveKin, "not a MoorDyn v2 option (0 to 7)");
    }
    switch (currents) {
        case 0: break;
        case 1:
            if (!file(currentRow, "Currents", currents, kCurrentProfileFile, text)) return false;
            if (!read_current_profile(*text, sea, what)) return refuse(currentRow, "Currents", currents, what);
            notes.push_back(at_line(currentRow, "Currents 1: the steady profile of current_profile.txt is the current "
                                                "profile currentProfile.* (" + std::to_string(sea.profileRows) +
                                                " rows, in place of the parameters'; added to the inputs current.x/y)"));
            break;
        case 2: case 5: {
            const char* name = currents == 2 ? kCurrentDynamicFile : kCurrent4dFile;
            if (!file(currentRow, "Currents", currents, name, text)) return false;
            std::string why;
            sea.currentGrid = CurrentGrid::read(currents, text->text, why);
            if (!sea.currentGrid) return refuse(currentRow, "Currents", currents, std::string(name) + ": " + why);
            sea.currentsMode = currents;
            sea.currentsFile = name;
            notes.push_back(at_line(currentRow, "Currents " + std::to_string(currents) + ": " + name + ", " +
                                                sea.currentGrid->describe() + ", is the current given as data "
                                                "(currents.mode " + std::to_string(currents) + "), interpolated as MoorDyn "
                                                "does and added to the inputs current.x/y at every point (also where "
                                                "MoorDyn adds it onto its wave grid)"));
            break;
        }
        case 3: case 4:
            return refuse(currentRow, "Currents", currents, "not implemented in MoorDyn v2 either");
        default:
            return refuse(currentRow, "Currents", currents, "not a MoorDyn v2 option (0 to 5)");
    }
    return true;
}

bool read_seafloor(const LineFileCompanions& companions, LineFileSeabed& seabed, std::vector<std::string>& notes,
                   std::string& error) {
    if (seabed.seafloorFile.empty()) return true;
    const int row = seabed.seafloorFileRow;
    auto refuse = [&](const std::string& why) {
        error = at_line(row, "SeafloorFile " + quoted(seabed.seafloorFile) + ": " + why);
        return false;
    };
    const LineFileCompanion* file = companion(companions, seabed.seafloorFile.c_str());
    if (!file) return refuse("it could not be read (looked up from the deck's directory, there also without its "
                             "leading directories, and from the working directory)");
    std::vector<NumberRow> rows;
    std::string what;
    if (!number_rows(*file, 1, rows, what)) return refuse(what);
    // MoorDyn's grid: nx ny, the nx x values, the ny y values, then rows x y z (the seabed's height)
    if (rows.size() < 3 || rows[0].values.size() != 2) return refuse("the first line must give the grid's nx and ny");
    const double nxValue = rows[0].values[0], nyValue = rows[0].values[1];
    if (!(nxValue >= 1 && nyValue >= 1 && nxValue == std::floor(nxValue) && nyValue == std::floor(nyValue)))
        return refuse("nx and ny must be whole numbers of at least 1");
    const size_t nx = static_cast<size_t>(nxValue), ny = static_cast<size_t>(nyValue);
    if (rows[1].values.size() != nx || rows[2].values.size() != ny || rows.size() != 3 + nx * ny)
        return refuse("expected " + std::to_string(nx) + " x values, " + std::to_string(ny) + " y values and " +
                      std::to_string(nx * ny) + " rows x y z");
    // the least-squares plane z = a + b x + c y through the grid's points
    double S[3][3] = {}, t[3] = {}, extent = 0.0, height = 0.0;
    for (size_t k = 3; k < rows.size(); ++k) {
        if (rows[k].values.size() != 3) return refuse("line " + std::to_string(rows[k].number) + ": expected x y z");
        const double phi[3] = {1.0, rows[k].values[0], rows[k].values[1]}, z = rows[k].values[2];
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) S[i][j] += phi[i] * phi[j];
            t[i] += phi[i] * z;
        }
        extent = std::max({extent, std::abs(phi[1]), std::abs(phi[2])});
        height = std::max(height, std::abs(z));
    }
    Eigen::Matrix3d M;
    Eigen::Vector3d r;
    for (int i = 0; i < 3; ++i) {
        r[i] = t[i];
        for (int j = 0; j < 3; ++j) M(i, j) = S[i][j];
    }
    // a grid of one row or column fixes no slope across it: the plane is level that way
    for (int i = 1; i < 3; ++i)
        if (M(i, i) * M(0, 0) - M(0, i) * M(0, i) <= 1e-12 * M(i, i) * M(0, 0)) {
            M.row(i).setZero();
            M.col(i).setZero();
            M(i, i) = 1.0;
            r[i] = 0.0;
        }
    const Eigen::Vector3d abc = M.ldlt().solve(r);
    double off = 0.0;
    for (size_t k = 3; k < rows.size(); ++k)
        off = std::max(off, std::abs(abc[0] + abc[1] * rows[k].values[0] + abc[2] * rows[k].values[1] - rows[k].values[2]));
    const double tolerance = 1e-6 * std::max({extent, height, 1.0});  // the file's printed digits
    if (!(off <= tolerance)) {
        // a grid: the seabed interpolated in it (seabed.file), the water depth its mean depth as MoorDyn's
        std::string why;
        seabed.grid = SeabedGrid::read(file->text, why);
        if (!seabed.grid) return refuse(why);
        seabed.meanDepth = -seabed.grid->mean_height();
        notes.push_back(at_line(row, "SeafloorFile: its grid is not a plane (a point lies " + number_text(off) +
                                         " m off the best plane): the seabed is the grid (seabed.file), " +
                                         seabed.grid->describe() + ", interpolated bilinearly as MoorDyn does, contact "
                                         "along its local normal; the water depth of the waves its mean depth " +
                                         number_text(seabed.meanDepth) + " m (waterDepth, in place of WtrDpth's)"));
        return true;
    }
    seabed.plane = true;
    seabed.planeDepth = -abc[0];
    const double gradient = std::hypot(abc[1], abc[2]);
    seabed.slope = std::atan(gradient) * 180.0 / kPi;
    seabed.heading = gradient > 0.0 ? std::atan2(-abc[2], -abc[1]) * 180.0 / kPi : 0.0;  // where it descends
    notes.push_back(at_line(row, "SeafloorFile: its grid is a plane, the seabed " + number_text(seabed.planeDepth) +
                                     " m deep under the origin (waterDepth, in place of WtrDpth's) sloping " +
                                     number_text(seabed.slope) + " deg down towards the heading " +
                                     number_text(seabed.heading) + " deg (seabedSlope, seabedSlopeHeading)"));
    return true;
}

}  // namespace deck

std::vector<std::string> line_file_companions(std::string_view text) {
    using namespace deck;
    std::vector<std::optional<Section>> sections;
    std::string error;
    std::vector<std::string> names, notes;
    Options options;
    if (!collect_sections(text, sections, error)) return names;
    const auto& o = sections[static_cast<size_t>(Kind::Options)];
    if (o && read_options(*o, options, notes, error)) {
        if (options.waveKin.first == 7 || options.waveKin.first == 2) names.push_back(kWaveFrequenciesFile);
        if (options.waveKin.first == 3) names.push_back(kWaveElevationFile);
        if (options.currents.first == 1) names.push_back(kCurrentProfileFile);
        if (options.currents.first == 2) names.push_back(kCurrentDynamicFile);
        if (options.currents.first == 5) names.push_back(kCurrent4dFile);
        if (!options.seabed.seafloorFile.empty()) names.push_back(options.seabed.seafloorFile);
    }
    if (const auto& types = sections[static_cast<size_t>(Kind::LineTypes)]) {
        for (const Row& row : types->rows) {
            const std::string_view file = tension_strain_file(row);
            if (!file.empty() && std::find(names.begin(), names.end(), file) == names.end()) names.emplace_back(file);
        }
    }
    return names;
}

std::vector<std::string> line_file_nested_companions(std::string_view text, std::string_view name, std::string_view companion) {
    using namespace deck;
    std::vector<std::optional<Section>> sections;
    std::string error;
    std::vector<std::string> names;
    if (!collect_sections(text, sections, error)) return names;
    const auto& types = sections[static_cast<size_t>(Kind::LineTypes)];
    if (!types) return names;
    for (const Row& row : types->rows) {
        // a Syrope settings file names its original working curve's file
        if (row.tokens.size() < 4 || upper(row.tokens[3]).rfind("SYROPE:", 0) != 0 || tension_strain_file(row) != name) continue;
        std::string owc, what;
        int form = 0;
        double k1 = 0.0, k2 = 0.0;
        read_syrope_settings(companion, std::string(name), owc, form, k1, k2, what);
        if (!owc.empty()) names.push_back(owc);
        break;
    }
    return names;
}

}  // namespace uc

namespace uc {

bool read_wave_file(std::string_view text, double direction, std::vector<std::array<double, 4>>& components,
                    std::string& error) {
    using namespace deck;
    components.clear();
    const std::vector<std::string_view> lines = split_lines(text);
    for (size_t i = 0; i < lines.size(); ++i) {
        const std::vector<std::string_view> tokens = tokenize(lines[i]);
        if (tokens.empty() || tokens[0].front() == '#') continue;  // blank, or a comment
        const std::string at = "line " + std::to_string(i + 1) + ": ";
        if (tokens.size() < 3 || tokens.size() > 4) {
            error = at + "a row is omega [rad/s] amplitude [m] phase [rad] [direction, rad] (a comment starts with #)";
            return false;
        }
        std::array<double, 4> c{0.0, 0.0, 0.0, direction};
        for (size_t k = 0; k < tokens.size(); ++k) {
            const std::optional<double> v = to_number(tokens[k]);
            if (!v) {
                error = at + quoted(tokens[k]) + " is not a number";
                return false;
            }
            c[k] = *v;
        }
        components.push_back(c);
    }
    if (components.empty()) {
        error = "no rows of components (omega [rad/s] amplitude [m] phase [rad] [direction, rad])";
        return false;
    }
    return true;
}

bool apply_wave_components(const std::vector<std::array<double, 4>>& components, const char* from, UCParams& p,
                           std::string& error) {
    if (components.size() > static_cast<size_t>(UC_MAX_WAVE_COMPONENTS)) {
        error = std::string(from) + ": " + std::to_string(components.size()) + " wave components, the FMU holds " +
                std::to_string(UC_MAX_WAVE_COMPONENTS) + " (waves.mode 3)";
        return false;
    }
    p.waveComponentCount = static_cast<int>(components.size());
    for (size_t k = 0; k < components.size(); ++k) std::copy(components[k].begin(), components[k].end(), p.waveComponents + 4 * k);
    return true;
}

}  // namespace uc
