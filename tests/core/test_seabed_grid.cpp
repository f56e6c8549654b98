// A seabed given as a grid of heights (docs/model.md, "A seabed given as a grid"): MoorDyn's SeafloorFile
// and MoorPy's bathymetry file read alike, interpolated bilinearly and held at the edges, refused naming the
// line; the contact on the grid's local plane, the plane's own contact where the grid is a plane.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "terms/seabed.h"
#include "terms/seabed_grid.h"

using namespace uc;

namespace {

using Height = std::function<double(double, double)>;

const std::vector<double> kX = {-300.0, -120.0, -40.0, 0.0, 75.0, 210.0};
const std::vector<double> kY = {-80.0, -10.0, 30.0, 95.0};

// MoorDyn's SeafloorFile of the heights f at the nodes (rows y fastest, as MoorDyn's example writes them).
std::string moordyn_text(const Height& f, const std::vector<double>& x = kX, const std::vector<double>& y = kY) {
    std::ostringstream s;
    s.precision(17);
    s << x.size() << " " << y.size() << "\n";
    for (double v : x) s << v << " ";
    s << "\n";
    for (double v : y) s << v << " ";
    s << "\n";
    for (double a : x)
        for (double b : y) s << a << " " << b << " " << f(a, b) << "\n";
    return s.str();
}

// MoorPy's bathymetry file of the same heights (depths, positive down; a row per y).
std::string moorpy_text(const Height& f, const std::vector<double>& x = kX, const std::vector<double>& y = kY) {
    std::ostringstream s;
    s.precision(17);
    s << "--- MoorPy bathymetry ---\nnGridX " << x.size() << "\nnGridY " << y.size() << "\n";
    for (double v : x) s << v << " ";
    s << "\n";
    for (double b : y) {
        s << b;
        for (double a : x) s << " " << -f(a, b);
        s << "\n";
    }
    return s.str();
}

double ridge(double x, double y) { return -100.0 + 12.0 * std::exp(-x * x / 8000.0) + 0.02 * y - 1e-4 * x * y; }

std::shared_ptr<const SeabedGrid> read_ok(const std::string& text) {
    std::string error;
    auto grid = SeabedGrid::read(text, error);
    EXPECT_TRUE(grid) << error;
    return grid;
}

std::string refusal(const std::string& text) {
    std::string error;
    EXPECT_FALSE(SeabedGrid::read(text, error));
    return error;
}

}  // namespace

TEST(SeabedGrid, MoorDynsSeafloorFileAndMoorPysBathymetryFileGiveOneGrid) {
    const auto md = read_ok(moordyn_text(ridge)), mp = read_ok(moorpy_text(ridge));
    ASSERT_TRUE(md && mp);
    EXPECT_EQ(md->x(), kX);
    EXPECT_EQ(md->y(), kY);
    for (size_t i = 0; i < kX.size(); ++i)
        for (size_t j = 0; j < kY.size(); ++j) {
            EXPECT_EQ(md->node(i, j), ridge(kX[i], kY[j]));
            EXPECT_EQ(mp->node(i, j), md->node(i, j));  // MoorPy's depth is minus the height, exactly
        }
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> ux(-400.0, 300.0), uy(-120.0, 140.0);
    for (int k = 0; k < 200; ++k) {
        const double x = ux(rng), y = uy(rng);
        EXPECT_EQ(md->height(x, y), mp->height(x, y));
    }
    // MoorDyn's rows may come in any order: the reversed file is the same grid
    std::string text = moordyn_text(ridge), head, rows;
    std::istringstream in(text);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    std::string reversed = lines[0] + "\n" + lines[1] + "\n" + lines[2] + "\n";
    for (size_t k = lines.size(); k-- > 3;) reversed += lines[k] + "\n";
    const auto back = read_ok(reversed);
    for (size_t i = 0; i < kX.size(); ++i)
        for (size_t j = 0; j < kY.size(); ++j) EXPECT_EQ(back->node(i, j), md->node(i, j));
}

TEST(SeabedGrid, BilinearInEachCellHeldAtTheEdgeOutside) {
    // a bilinear function is its own bilinear interpolant: heights and gradients to round-off
    const auto f = [](double x, double y) { return -80.0 + 0.03 * x - 0.05 * y + 2e-4 * x * y; };
    const auto grid = read_ok(moordyn_text(f));
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> ux(-300.0, 210.0), uy(-80.0, 95.0);
    for (int k = 0; k < 200; ++k) {
        const double x = ux(rng), y = uy(rng);
        double gx = 0.0, gy = 0.0;
        EXPECT_NEAR(grid->height(x, y, &gx, &gy), f(x, y), 1e-12 * 100.0);
        EXPECT_NEAR(gx, 0.03 + 2e-4 * y, 1e-13);
        EXPECT_NEAR(gy, -0.05 + 2e-4 * x, 1e-13);
    }
    // outside: the edge's height, level across the edge (MoorDyn's interp_factor, MoorPy's getInterpNums)
    double gx = 0.0, gy = 0.0;
    EXPECT_EQ(grid->height(-900.0, 12.0, &gx, &gy), grid->height(-300.0, 12.0));
    EXPECT_EQ(gx, 0.0);
    EXPECT_NEAR(gy, -0.05 + 2e-4 * -300.0, 1e-13);
    EXPECT_EQ(grid->height(500.0, 400.0, &gx, &gy), f(210.0, 95.0));
    EXPECT_EQ(gx, 0.0);
    EXPECT_EQ(gy, 0.0);
    // a curved seabed: between the nodes the interpolant, not the function (the ridge's crest is cut)
    const auto bumpy = read_ok(moordyn_text(ridge));
    const double x = -20.0, y = 50.0, fx = (x - -40.0) / 40.0, fy = (y - 30.0) / 65.0;
    const double expected = (1 - fy) * ((1 - fx) * ridge(-40, 30) + fx * ridge(0, 30)) +
                            fy * ((1 - fx) * ridge(-40, 95) + fx * ridge(0, 95));
    EXPECT_NEAR(bumpy->height(x, y), expected, 1e-12);
    EXPECT_NEAR(bumpy->mean_height(), [] {
        double s = 0.0;
        for (double a : kX)
            for (double b : kY) s += ridge(a, b);
        return s / (kX.size() * kY.size());
    }(), 1e-12);
}

TEST(SeabedGrid, ABadFileIsRefusedNamingItsLine) {
    const auto flat = [](double, double) { return -50.0; };
    // x not ascending, on line 2
    std::string e = refusal(moordyn_text(flat, {0.0, 10.0, 5.0}, {0.0, 1.0}));
    EXPECT_NE(e.find("line 2: x = 5 after 10: the values must increase"), std::string::npos) << e;
    e = refusal(moorpy_text(flat, {0.0, 10.0}, {3.0, 1.0}));
    EXPECT_NE(e.find("line 6: y = 1 after 3: the values must increase"), std::string::npos) << e;
    // a missing point (MoorDyn takes 0 for it)
    std::string text = moordyn_text(flat, {0.0, 10.0}, {0.0, 1.0});
    text = text.substr(0, text.rfind('\n', text.size() - 2) + 1);
    e = refusal(text);
    EXPECT_NE(e.find("without the grid point (10, 1)"), std::string::npos) << e;
    // a point given twice
    e = refusal(moordyn_text(flat, {0.0, 10.0}, {0.0, 1.0}) + "0 0 -3\n");
    EXPECT_NE(e.find("line 8: the grid point (0, 0) is given a second time (first on line 4)"), std::string::npos) << e;
    // a point off the axes, a count that does not match, a word where a number goes
    e = refusal("2 2\n0 10\n0 1\n0 0 -5\n0 1 -5\n10 0 -5\n11 1 -5\n");
    EXPECT_NE(e.find("line 7: x = 11 is none of the grid's x values"), std::string::npos) << e;
    e = refusal("3 2\n0 10\n0 1\n");
    EXPECT_NE(e.find("line 2: 2 x values where the first line gives nx = 3"), std::string::npos) << e;
    e = refusal("2 2\n0 10\n0 1\n0 0 -5\n0 1 deep\n");
    EXPECT_NE(e.find("line 5: 'deep' is not a number"), std::string::npos) << e;
    e = refusal("2.5 2\n0 10\n0 1\n");
    EXPECT_NE(e.find("line 1: nx = 2.5"), std::string::npos) << e;
    e = refusal("title\nnGridX 2\nnGridY 2\n0 10\n0 5 5\n");
    EXPECT_NE(e.find("1 lines of depths where nGridY = 2"), std::string::npos) << e;
    e = refusal("title\nnGridX 2\nnGridY 1\n0 10\n0 5\n");
    EXPECT_NE(e.find("line 5: 2 values where a line of depths holds y and nGridX = 2 depths"), std::string::npos) << e;
    e = refusal("a seabed\n");
    EXPECT_NE(e.find("line 1: neither MoorDyn's SeafloorFile"), std::string::npos) << e;
    e = refusal("\n\n");
    EXPECT_NE(e.find("the file is empty"), std::string::npos) << e;
}

namespace {

SeabedProps contact(double depth) {
    SeabedProps p;
    p.enabled = true;
    p.depth = depth;
    p.stiffness = 2e5;
    p.damping = 3e3;
    p.friction = 0.6;
    p.smoothing = 0.005;
    return p;
}

}  // namespace

TEST(SeabedGrid, AGridThatIsAPlaneIsThePlaneToRoundOff) {
    // the plane 120 m deep under the origin descending 7 deg towards 30 deg
    const double slope = 7.0, heading = 30.0, depth = 120.0;
    SeabedProps plane = contact(depth);
    set_slope(plane, slope, heading);
    const Vec3 n = plane.normal;
    const auto height = [&](double x, double y) { return -depth - (n.x() * x + n.y() * y) / n.z(); };
    const auto grid = read_ok(moordyn_text(height));
    SeabedProps onGrid = contact(depth);
    set_grid(onGrid, grid.get());
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> ux(-290.0, 200.0), uy(-75.0, 90.0), pen(-0.002, 0.02), v(-0.3, 0.3);
    for (int rest = 0; rest < 2; ++rest) {
        if (rest) {  // seabedRest 1: both raised by the rest penetration of 400 N/m
            rest_at_depth(plane, 400.0);
            rest_at_depth(onGrid, 400.0);
        }
        for (int k = 0; k < 100; ++k) {
            const double x = ux(rng), y = uy(rng);
            const Vec3 r = Vec3(x, y, seabed_height(plane, x, y)) - pen(rng) * n;
            const Vec3 rd(v(rng), v(rng), v(rng));
            SeabedJacobian Jp, Jg;
            const Vec3 Fp = seabed_load(plane, r, rd, &Jp), Fg = seabed_load(onGrid, r, rd, &Jg);
            const double scale = plane.stiffness * 0.03;
            EXPECT_LT((Fp - Fg).norm(), 1e-9 * scale) << x << " " << y;
            EXPECT_LT((Jp.dr - Jg.dr).norm(), 1e-9 * plane.stiffness);
            EXPECT_LT((Jp.drd - Jg.drd).norm(), 1e-9 * (plane.damping + plane.friction * scale / 0.01));
            EXPECT_NEAR(seabed_height(plane, x, y), seabed_height(onGrid, x, y), 1e-10);
        }
    }
}

TEST(SeabedGrid, ContactActsAlongTheGridsLocalNormalAndFrictionAlongItsSurface) {
    const auto grid = read_ok(moordyn_text(ridge));
    SeabedProps p = contact(0.0);
    set_grid(p, grid.get());
    const double x = -60.0, y = 12.0;
    double gx = 0.0, gy = 0.0;
    const double h = grid->height(x, y, &gx, &gy);
    const Vec3 n = Vec3(-gx, -gy, 1.0).normalized();
    ASSERT_GT(std::hypot(gx, gy), 0.05);  // on the ridge's flank
    const Vec3 r(x, y, h - 0.01 / n.z());  // under (x, y): 0.01 m along the local normal
    // at rest: along n, the penetration n_z (h - z) on the ramp's linear branch
    const Vec3 F = seabed_load(p, r, Vec3::Zero(), nullptr);
    EXPECT_LT((F.normalized() + n).norm(), 1e-12);
    const double penetration = n.z() * (h - r.z());
    EXPECT_NEAR(penetration, 0.01, 1e-12);
    EXPECT_NEAR(F.norm(), p.stiffness * (penetration - 0.5 * p.smoothing), 1e-9);
    // sliding along the surface: the friction opposes the velocity, in the surface
    const Vec3 along = Vec3(1.0, 0.0, gx).normalized();
    const Vec3 Fs = seabed_load(p, r, 0.5 * along, nullptr);
    const Vec3 friction = Fs - F;  // the residual holds minus the load: +mu k g v / |v|
    EXPECT_NEAR(friction.dot(n), 0.0, 1e-9 * F.norm());
    EXPECT_GT(friction.dot(along), 0.0);
    // the Jacobian against central differences, inside one cell (the normal's turning left out: below
    // the weight-scale twist of the cell, 1e-4 of the contact stiffness here)
    SeabedJacobian J;
    const Vec3 rd(0.05, -0.02, 0.01);
    seabed_load(p, r, rd, &J);
    for (int c = 0; c < 3; ++c) {
        Vec3 e = Vec3::Zero();
        e[c] = 1e-6;
        const Vec3 d = (seabed_load(p, r + e, rd, nullptr) - seabed_load(p, r - e, rd, nullptr)) / 2e-6;
        EXPECT_LT((d - J.dr.col(c)).norm(), 2e-3 * p.stiffness) << c;
    }
}

TEST(SeabedGrid, AnElementAboveTheGridIsSkippedOnlyWhereNoPointTouches) {
    const auto grid = read_ok(moordyn_text(ridge));
    SeabedProps p = contact(0.0);
    set_grid(p, grid.get());
    rest_at_depth(p, 300.0);
    const ElementTables e = make_element_tables(8.0, 3, 3, 1.0);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> ux(-320.0, 220.0), uy(-90.0, 100.0), dz(-0.5, 3.0), t(-1.0, 1.0);
    int skipped = 0, kept = 0;
    for (int k = 0; k < 2000; ++k) {
        double X[12];
        const double x = ux(rng), y = uy(rng);
        const Vec3 tangent = Vec3(t(rng), t(rng), 0.3 * t(rng)).normalized();
        const Vec3 a(x, y, grid->height(x, y) + dz(rng)), b = a + 8.0 * tangent + Vec3(0.0, 0.0, dz(rng) - 1.0);
        for (int c = 0; c < 3; ++c) {
            X[c] = a[c];
            X[3 + c] = tangent[c];
            X[6 + c] = b[c];
            X[9 + c] = tangent[c];
        }
        const bool above = above_contact(e, p, X);
        (above ? skipped : kept)++;
        if (!above) continue;
        const ContactPoints points = contact_points(e);
        for (int g = 0; g < points.count; ++g)
            EXPECT_TRUE(seabed_load(p, interpolate(points.points[g].shape.N, X), Vec3::Zero(), nullptr).isZero(0.0));
    }
    EXPECT_GT(skipped, 200);
    EXPECT_GT(kept, 200);
}
