// line_types.cpp - the LINE TYPES section of a MoorDyn v2 deck, with the tension-strain files its EA may name
// (docs/lines.md).
#include "deck/tables.h"

#include <algorithm>
#include <cmath>

#include "terms/axial_curve.h"
#include "terms/syrope.h"

namespace uc {
namespace deck {

namespace {

// The index of the column named MBL among the table's column names (after MoorDyn's ten), -1 when none.
int breaking_load_column(const Row& columns) {
    for (size_t i = 10; i < columns.tokens.size(); ++i) {
        if (upper(columns.tokens[i]) == "MBL") return static_cast<int>(i);
    }
    return -1;
}

// MoorDyn's tension-strain file: three header lines, then rows "strain tension" (further fields ignored),
// up to the end or a line of dashes (MoorPy's end mark); blank lines are skipped.
bool read_curve_file(const LineFileCompanion& file, std::vector<double>& strain, std::vector<double>& tension,
                     std::string& what) {
    const std::vector<std::string_view> lines = split_lines(file.text);
    for (size_t i = 3; i < lines.size(); ++i) {
        if (lines[i].find("---") != std::string_view::npos) break;
        const std::vector<std::string_view> tokens = tokenize(lines[i]);
        if (tokens.empty()) continue;
        const std::optional<double> e = to_number(tokens[0]);
        const std::optional<double> T = tokens.size() > 1 ? to_number(tokens[1]) : std::nullopt;
        if (!e || !T) {
            what = file.name + " line " + std::to_string(i + 1) + ": " + quoted(lines[i]) +
                   " is not a row of two numbers (strain, tension [N])";
            return false;
        }
        strain.push_back(*e);
        tension.push_back(*T);
    }
    if (strain.size() > UC_AXIAL_CURVE_POINTS) {
        what = file.name + ": " + std::to_string(strain.size()) + " points, more than the " +
               std::to_string(UC_AXIAL_CURVE_POINTS) + " a curve holds (MoorDyn's limit too)";
        return false;
    }
    AxialCurve curve;
    std::string why;
    if (!AxialCurve::build(strain.data(), tension.data(), static_cast<int>(strain.size()), curve, why)) {
        what = file.name + ": " + why;
        return false;
    }
    return true;
}

// The fields of an entry separated by `mark` (MoorDyn's EA_s|EA_d, a SYROPE IC row's 1,2,3); one field where
// there is no mark.
std::vector<std::string_view> split_list(std::string_view text, char mark) {
    std::vector<std::string_view> parts;
    size_t start = 0;
    for (size_t bar = text.find(mark); bar != std::string_view::npos; bar = text.find(mark, start)) {
        parts.push_back(text.substr(start, bar - start));
        start = bar + 1;
    }
    parts.push_back(text.substr(start));
    return parts;
}

std::vector<std::string_view> split_bars(std::string_view text) { return split_list(text, '|'); }

// The Syrope model of a line type (its curve read), with the start's tensions.
SyropeProps syrope_of(const LineType& t, double Tmax0, double Tmean0) {
    SyropeProps model;
    model.form = t.syropeForm;
    model.k1 = t.syropeK1;
    model.k2 = t.syropeK2;
    model.alpha = t.EAd;
    model.beta = t.EAslope;
    model.tensionMax0 = Tmax0;
    model.tensionMean0 = Tmean0;
    std::string why;  // (read_curve_file built it already)
    AxialCurve::build(t.curveStrain.data(), t.curveTension.data(), static_cast<int>(t.curveStrain.size()), model.owc, why);
    model.strain0 = t.curveStrain[0];
    return model;
}

}  // namespace

std::string_view tension_strain_file(const Row& row) {
    if (row.tokens.size() < 4) return {};
    const std::string_view ea = row.tokens[3];
    if (upper(ea).rfind("SYROPE:", 0) == 0) return split_bars(ea.substr(7))[0];
    if (to_number(ea) || ea.find('|') != std::string_view::npos) return {};
    return ea;
}

bool read_syrope_settings(std::string_view text, const std::string& name, std::string& owc, int& form, double& k1,
                          double& k2, std::string& what) {
    bool has[4] = {false, false, false, false};
    const std::vector<std::string_view> lines = split_lines(text);
    for (size_t i = 0; i < lines.size(); ++i) {
        const std::vector<std::string_view> tokens = tokenize(lines[i]);
        if (tokens.size() < 2) continue;  // (MoorDyn skips such a row too)
        const std::string key = lower(tokens[1]);
        const std::string at = name + " line " + std::to_string(i + 1) + ": ";
        if (key == "owc") {
            owc = std::string(tokens[0]);
            has[0] = true;
        } else if (key == "wctype") {
            form = syrope_form(std::string(tokens[0]));
            if (form == kSyropeNone) {
                what = at + "WCType " + quoted(tokens[0]) + " is not a working-curve formula (LINEAR, QUADRATIC or EXP)";
                return false;
            }
            has[1] = true;
        } else if (key == "k1" || key == "k2") {
            const std::optional<double> v = to_number(tokens[0]);
            if (!v) {
                what = at + key + " " + quoted(tokens[0]) + " is not a number";
                return false;
            }
            (key == "k1" ? k1 : k2) = *v;
            has[key == "k1" ? 2 : 3] = true;
        }
    }
    const char* names[4] = {"OWC (the original working curve's file)", "WCType (LINEAR, QUADRATIC or EXP)", "k1", "k2"};
    for (int k = 0; k < 4; ++k) {
        if (!has[k]) {
            what = name + ": no row \"<value> " + std::string(names[k]).substr(0, std::string(names[k]).find(' ')) +
                   "\" gives " + names[k] + " (a Syrope settings file has rows for OWC, WCType, k1 and k2)";
            return false;
        }
    }
    return true;
}

bool read_line_type(const Row& deckRow, const Row& columns, const LineFileCompanions& companions, LineType& t,
                    std::string& error) {
    // The MBL column is read here and taken out of the row; the rest is MoorDyn's row.
    const int mblColumn = breaking_load_column(columns);
    t.MBL = 0.0;
    Row row = deckRow;
    if (mblColumn >= 0) {
        Fields m(deckRow, error);
        if (static_cast<int>(deckRow.tokens.size()) <= mblColumn) {
            return m.fail("the column names (line " + std::to_string(columns.number) + ") have MBL as column " +
                          std::to_string(mblColumn + 1) + ", this row has " + std::to_string(deckRow.tokens.size()) +
                          " fields: give every line type its MBL [N]");
        }
        t.MBL = m.positive(static_cast<size_t>(mblColumn), "MBL");
        if (!m.ok()) {
            error += " (the minimum breaking load [N] of line type " + quoted(deckRow.tokens[0]) + ")";
            return false;
        }
        row.tokens.erase(row.tokens.begin() + mblColumn);
    }
    Fields f(row, error);
    const size_t n = row.tokens.size();
    if (n != 10 && n != 11 && n != 13) {
        return f.fail("a line type has 10 fields (TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx), "
                      "optionally followed by Cl or by Cl dF cF; this row has " + std::to_string(n));
    }
    t.name = std::string(row.tokens[0]);
    t.row = row.number;
    t.diameter = f.positive(1, "Diam");
    t.massPerLength = f.positive(2, "Mass/m");
    const std::string_view ea = f.token(3), ba = f.token(4);
    t.EAd = t.EAslope = t.BAd = 0.0;
    t.syropeForm = 0;
    const std::vector<std::string_view> eaParts = split_bars(ea);
    if (upper(ea).rfind("SYROPE:", 0) == 0) {
        // MoorDyn's Syrope model: SYROPE:<settings file>|EA_Dc|EA_D_Lm, the settings naming the original
        // working curve's file (relative to the deck), the working curve's formula and its k1, k2
        std::optional<double> alpha, beta;
        if (eaParts.size() == 3) {
            alpha = to_number(eaParts[1]);
            beta = to_number(eaParts[2]);
        }
        if (!alpha || !beta) {
            return f.fail("EA " + quoted(ea) + ": a Syrope EA is SYROPE:<settings file>|EA_Dc|EA_D_Lm, the file and "
                          "two numbers (the dynamic stiffness EA_Dc [N] and its slope in the mean tension EA_D_Lm)");
        }
        const std::string settingsName(eaParts[0].substr(7));
        const LineFileCompanion* settings = nullptr;
        for (const LineFileCompanion& c : companions)
            if (c.name == settingsName) settings = &c;
        if (!settings) {
            return f.fail("EA " + quoted(ea) + ": the Syrope settings file " + quoted(settingsName) +
                          " is not next to the deck, or cannot be read");
        }
        std::string owcName, what;
        if (!read_syrope_settings(settings->text, settingsName, owcName, t.syropeForm, t.syropeK1, t.syropeK2, what))
            return f.fail("EA " + quoted(ea) + ": " + what);
        const LineFileCompanion* owc = nullptr;
        for (const LineFileCompanion& c : companions)
            if (c.name == owcName) owc = &c;
        if (!owc) {
            return f.fail("EA " + quoted(ea) + ": the original working curve's file OWC " + quoted(owcName) + " (" +
                          settingsName + ", relative to the deck) cannot be read");
        }
        if (!read_curve_file(*owc, t.curveStrain, t.curveTension, what))
            return f.fail("EA " + quoted(ea) + ": the original working curve OWC: " + what);
        t.EA = t.curveTension.back() / t.curveStrain.back();
        t.EAd = *alpha;
        t.EAslope = *beta;
        // (the SYROPE IC rows are checked with the lines)
        const std::string why = syrope_check(syrope_of(t, -1.0, 0.0), "");
        if (!why.empty()) return f.fail("EA " + quoted(ea) + " (" + settingsName + "): " + why);
    } else if (eaParts.size() > 1) {
        // MoorDyn's viscoelastic model: EA_s|EA_d (a constant dynamic stiffness) or EA_s|EA_Dc|EA_D_Lm (EA_d =
        // EA_Dc + EA_D_Lm x the mean load)
        std::optional<double> v[3];
        for (size_t k = 0; k < eaParts.size() && k < 3; ++k) v[k] = to_number(eaParts[k]);
        if (eaParts.size() > 3 || !v[0] || !v[1] || (eaParts.size() == 3 && !v[2])) {
            return f.fail("EA " + quoted(ea) + ": a viscoelastic EA is EA_s|EA_d or EA_s|EA_Dc|EA_D_Lm, two or three "
                          "numbers (a tension-strain file with it is not supported)");
        }
        if (!(*v[0] > 0.0) || !(*v[1] > *v[0]) || (eaParts.size() == 3 && !(*v[2] >= 0.0))) {
            return f.fail("EA " + quoted(ea) + ": the viscoelastic model needs EA_s > 0 [N], a dynamic stiffness above "
                          "it [N] (the springs are in series) and a slope EA_D_Lm >= 0");
        }
        t.EA = *v[0];
        t.EAd = *v[1];
        t.EAslope = eaParts.size() == 3 ? *v[2] : 0.0;
    } else if (!to_number(ea)) {
        // A tension-strain file next to the deck; EA is its secant at the last point, as MoorDyn has it.
        const LineFileCompanion* file = nullptr;
        for (const LineFileCompanion& c : companions)
            if (c.name == ea) file = &c;
        if (!file) {
            return f.fail("EA " + quoted(ea) + ": the tension-strain file is not next to the deck, or cannot be read");
        }
        std::string what;
        if (!read_curve_file(*file, t.curveStrain, t.curveTension, what)) return f.fail("EA " + quoted(ea) + ": " + what);
        t.EA = t.curveTension.back() / t.curveStrain.back();
    } else {
        t.EA = f.positive(3, "EA");
    }
    const std::vector<std::string_view> baParts = split_bars(ba);
    if (baParts.size() > 1) {
        const std::optional<double> s = to_number(baParts[0]), d = baParts.size() == 2 ? to_number(baParts[1]) : std::nullopt;
        if ((t.EAd == 0.0 && t.syropeForm == 0) || baParts.size() > 2) {
            return f.fail("BA/-zeta " + quoted(ba) + ": BA_s|BA_d belongs to a viscoelastic EA (EA_s|EA_d), which this "
                          "line type has not");
        }
        if (!s || !d || !(*d >= 0.0)) {
            return f.fail("BA/-zeta " + quoted(ba) + ": BA_s|BA_d is two numbers, BA_s [N s] or -zeta, and BA_d >= 0 [N s]");
        }
        t.BA = *s;
        t.BAd = *d;
    } else {
        if (!to_number(ba)) {
            return f.fail("BA/-zeta " + quoted(ba) + ": a non-linear damping (table) is not supported (one BA or -zeta)");
        }
        t.BA = f.number(4, "BA/-zeta");
    }
    if (t.syropeForm != 0 && t.BA < 0.0) {
        return f.fail("BA/-zeta " + quoted(ba) + ": the Syrope model's damping is BA_s|BA_d in N s (MoorDyn takes it "
                      "as given, not as a fraction of critical)");
    }
    if (t.EAd > 0.0 && t.BA == 0.0 && t.BAd == 0.0) {
        return f.fail("BA/-zeta " + quoted(ba) + ": the viscoelastic model needs a damping, BA_s or BA_d above 0 "
                      "(its internal strain moves through them)");
    }
    if (!to_number(f.token(5))) {
        return f.fail("EI " + quoted(f.token(5)) + ": a non-linear bending stiffness (table) is not supported");
    }
    t.EI = f.non_negative(5, "EI");
    t.Cd = f.non_negative(6, "Cd");
    t.Ca = f.non_negative(7, "Ca");
    t.CdAx = f.non_negative(8, "CdAx");
    t.CaAx = f.non_negative(9, "CaAx");
    t.Cl = 0.0;
    t.dF = 0.08;  // MoorDyn's defaults (Thorsen's synchronisation model) where the row gives Cl alone
    t.cF = 0.18;
    if (n > 10) {
        t.Cl = f.non_negative(10, "Cl");
        if (n == 13) {
            t.dF = f.non_negative(11, "dF");
            t.cF = f.number(12, "cF");
            if (f.ok() && t.Cl > 0.0 && !(t.cF > 0.0))
                return f.fail("cF = " + shown(f.token(12)) + ": the centre of the VIV model's non-dimensional shedding "
                              "frequencies is positive (Thorsen's 0.18)");
        }
    }
    return f.ok();
}

bool read_syrope_ic(const std::vector<Row>& rows, const std::vector<LineType>& types, std::vector<Line>& lines,
                    std::vector<std::string>& notes, std::string& error) {
    const bool any = std::any_of(lines.begin(), lines.end(), [&](const Line& l) { return types[l.type].syropeForm != 0; });
    if (!rows.empty() && !any) {
        error = at_line(rows[0].number, "a SYROPE IC section, but no line has the Syrope model (EA SYROPE:...)");
        return false;
    }
    for (const Row& row : rows) {
        Fields f(row, error);
        if (row.tokens.size() < 3) return f.fail("a SYROPE IC row is Line(s) Tmax0 Tmean0 (3 fields), this one has " +
                                                 std::to_string(row.tokens.size()));
        const double Tmax0 = f.positive(1, "Tmax0"), Tmean0 = f.non_negative(2, "Tmean0");
        if (!f.ok()) return false;
        for (std::string_view id : split_list(row.tokens[0], ',')) {
            const std::optional<double> n = to_number(id);
            if (!n || *n != std::floor(*n) || *n < 1 || *n > static_cast<double>(lines.size()))
                return f.fail("Line(s) " + quoted(row.tokens[0]) + ": " + quoted(id) + " is not a line of the deck (1 to " +
                              std::to_string(lines.size()) + ")");
            Line& l = lines[static_cast<size_t>(*n) - 1];
            const LineType& t = types[l.type];
            if (t.syropeForm == 0) {
                notes.push_back(at_line(row.number, "SYROPE IC row of line " + std::string(id) +
                                                        " ignored: its type " + quoted(t.name) + " has no Syrope model"));
                continue;
            }
            const std::string why = syrope_check(syrope_of(t, Tmax0, Tmean0), "");
            if (!why.empty()) return f.fail("SYROPE IC of line " + std::string(id) + ": " + why);
            l.syropeTmax0 = Tmax0;
            l.syropeTmean0 = Tmean0;
        }
    }
    for (const Line& l : lines) {
        if (types[l.type].syropeForm != 0 && l.syropeTmax0 < 0.0) {
            error = at_line(l.row, "line " + std::to_string(l.id) + " has the Syrope model (type " + quoted(types[l.type].name) +
                                       ") but no SYROPE IC row: give its Tmax0 and Tmean0 [N]");
            return false;
        }
    }
    return true;
}

}  // namespace deck
}  // namespace uc
