// The String parameter lineFile through the FMI: fmi2SetString/fmi2GetString by the FMI 2.0 rules (the
// string is copied; NULL and over-long strings are errors naming the variable), the path looked up in the
// resources directory first and then in the working directory, unreadable files and refused decks as
// errors naming the path (and the deck's line), and FMU states that do not read the file again.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "fmu_harness.h"
#include "variables.h"

namespace fs = std::filesystem;

namespace {

const fs::path kChainDeck = fs::path(UC_TEST_DATA_DIR) / "decks" / "chain.dat";

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

void write_text(const fs::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

// A fresh directory under the system's temporary directory, removed at the end of the test.
struct TempDir {
    fs::path path;
    TempDir() {
        std::string pattern = (fs::temp_directory_path() / "uc_line_file_XXXXXX").string();
        path = mkdtemp(pattern.data()) ? fs::path(pattern) : fs::path();
    }
    ~TempDir() {
        std::error_code ignored;
        fs::remove_all(path, ignored);
    }
};

// The file: URI of a directory, spaces and '%' percent-encoded as importers do.
std::string file_uri(const fs::path& dir) {
    std::string uri = "file://";
    for (char c : dir.string()) {
        if (c == ' ') {
            uri += "%20";
        } else if (c == '%') {
            uri += "%25";
        } else {
            uri += c;
        }
    }
    return uri;
}

// The chain of chain.dat described by parameters, as the reader maps it (docs/lines.md).
void set_chain_by_parameters(Instance& inst) {
    inst.setReal("length", 900.0);
    inst.setReal("diameter", 0.0766);
    inst.setReal("massPerLength", 113.0);
    inst.setReal("EA", 7.5e8);
    inst.setReal("EI", 0.0);
    inst.setReal("axialDamping", 0.8 * (900.0 / 40) * std::sqrt(7.5e8 * 113.0));  // BA/-zeta = -0.8, 40 segments
    inst.setReal("Cdn", 2.4);
    inst.setReal("Cdt", 0.2);
    inst.setReal("Can", 1.0);
    inst.setReal("Cat", 0.0);
    inst.setInteger("nElements", 20);  // NumSegs 40
    // the type named chain: MoorPy's R4 studless chain MBL at the nominal diameter of its 113 kg/m
    // (docs/design_checks.md), the same operations as the reader's
    const double d = std::sqrt(113.0 / 20.0e3);
    inst.setReal("MBL", d * (9.11e2 + d * (1.21e9 + d * -2.19e9)));
    inst.setInteger("bottomEnd", 1);
    inst.setReal("anchor.x", -850.0);
    inst.setReal("anchor.y", 0.0);
    inst.setReal("anchor.z", -320.0);
    inst.setReal("waterDepth", 320.0);
    inst.setReal("gravity", 9.81);
    inst.setReal("waterDensity", 1025.0);
    // the deck's seabed damping (MoorDyn's default cBot, the deck is silent, x Diam) and tension-only law
    inst.setReal("seabedDamping", 3.0e5 * 0.0766);
    const fmi2ValueReference compression = vr_of("enableCompression");
    const fmi2Boolean off = fmi2False;
    fmi().SetBoolean(inst.c, &compression, 1, &off);
}

// What a line file does not describe: set alongside it (or with the parameters).
void set_scene(Instance& inst) {
    const fmi2ValueReference seabed = vr_of("enableSeabed");
    const fmi2Boolean on = fmi2True;
    fmi().SetBoolean(inst.c, &seabed, 1, &on);
    inst.setReal("seabedStiffness", 1e6);
    inst.setReal("tow.z", -70.0);
    inst.setReal("tow.vx", 0.2);
}

// n steps of h with the fairlead surging at 0.2 m/s (position and velocity inputs consistent).
fmi2Status surge(Instance& inst, int n, double h, double* t) {
    for (int i = 0; i < n; ++i) {
        inst.setReal("tow.x", 0.2 * (*t + h));
        const fmi2Status s = inst.steps(1, h, t);
        if (s != fmi2OK) return s;
    }
    return fmi2OK;
}

}  // namespace

// fmi2Get* may be called from initialization mode on (FMI 2.0 section 4.2.4).
void enter_initialization_mode(Instance& inst) {
    ASSERT_EQ(inst.setup(), fmi2OK);
    ASSERT_EQ(fmi().EnterInitializationMode(inst.c), fmi2OK);
}

TEST(LineFileParameter, SetStringCopiesTheStringAndGetStringReturnsIt) {
    Instance inst;
    enter_initialization_mode(inst);
    EXPECT_EQ(inst.getString("lineFile"), "");
    char buffer[] = "decks/chain.dat";
    ASSERT_EQ(inst.setString("lineFile", buffer), fmi2OK);
    buffer[0] = 'X';  // the caller's memory is not kept
    EXPECT_EQ(inst.getString("lineFile"), "decks/chain.dat");
    ASSERT_EQ(inst.setString("lineFile", ""), fmi2OK);
    EXPECT_EQ(inst.getString("lineFile"), "");
}

TEST(LineFileParameter, NullAndOverLongStringsAreErrorsNamingTheVariable) {
    {
        Instance inst;
        EXPECT_EQ(inst.setString("lineFile", nullptr), fmi2Error);
        EXPECT_TRUE(inst.log.contains("fmi2SetString: lineFile: the value is a NULL pointer")) << inst.log.all();
    }
    {
        Instance inst;
        enter_initialization_mode(inst);
        const std::string longest(UC_STRING_CAPACITY - 1, 'a');
        EXPECT_EQ(inst.setString("lineFile", longest.c_str()), fmi2OK) << inst.log.all();
        EXPECT_EQ(inst.getString("lineFile"), longest);
        const std::string tooLong(UC_STRING_CAPACITY, 'a');
        EXPECT_EQ(inst.setString("lineFile", tooLong.c_str()), fmi2Error);
        EXPECT_TRUE(inst.log.contains("fmi2SetString: lineFile: the string is longer than the 4095 bytes"))
            << inst.log.all();
    }
    {
        Instance inst;
        const fmi2ValueReference vr = vr_of("lineFile");
        EXPECT_EQ(fmi().SetString(inst.c, &vr, 1, nullptr), fmi2Error);
        EXPECT_TRUE(inst.log.contains("vr or value is NULL")) << inst.log.all();
    }
    {
        Instance inst;
        const fmi2ValueReference vr = vr_of("lineFile");
        double x = 0.0;
        EXPECT_EQ(fmi().SetReal(inst.c, &vr, 1, &x), fmi2Error);  // a String is not a Real
        const fmi2ValueReference length = vr_of("length");
        const fmi2String value = "x";
        Instance other;
        EXPECT_EQ(fmi().SetString(other.c, &length, 1, &value), fmi2Error);
        EXPECT_TRUE(other.log.contains("length")) << other.log.all();
        EXPECT_TRUE(other.log.contains("use fmi2SetReal")) << other.log.all();
    }
}

TEST(LineFileParameter, ResetClearsTheString) {
    Instance inst;
    ASSERT_EQ(inst.setString("lineFile", "chain.dat"), fmi2OK);
    ASSERT_EQ(fmi().Reset(inst.c), fmi2OK);
    enter_initialization_mode(inst);
    EXPECT_EQ(inst.getString("lineFile"), "");
}

TEST(LineFileParameter, ADeckInTheResourcesIsTheSameLineAsItsParametersBitForBit) {
    TempDir tmp;
    const fs::path resources = tmp.path / "res dir%x";  // percent-encoded in the URI
    fs::create_directories(resources);
    fs::copy_file(kChainDeck, resources / "chain.dat");
    const std::string uri = file_uri(resources);
    Instance deck("deck", true, uri.c_str()), params("params");
    ASSERT_EQ(deck.setString("lineFile", "chain.dat"), fmi2OK);
    set_scene(deck);
    set_chain_by_parameters(params);
    set_scene(params);
    ASSERT_EQ(deck.initialize(), fmi2OK) << deck.log.all();
    ASSERT_EQ(params.initialize(), fmi2OK) << params.log.all();
    EXPECT_TRUE(deck.log.contains("lineFile " + (resources / "chain.dat").string() + " read")) << deck.log.all();
    EXPECT_TRUE(deck.log.contains("line 18: dtM ignored")) << deck.log.all();
    EXPECT_GT(deck.getReal("towTension"), 1.5e6);
    EXPECT_TRUE(bitwise_equal(deck.outputs(), params.outputs()));
    double t1 = 0.0, t2 = 0.0;
    ASSERT_EQ(surge(deck, 4, 0.5, &t1), fmi2OK) << deck.log.all();
    ASSERT_EQ(surge(params, 4, 0.5, &t2), fmi2OK) << params.log.all();
    EXPECT_TRUE(bitwise_equal(deck.outputs(), params.outputs()));
    EXPECT_EQ(deck.getString("lineFile"), "chain.dat");
}

TEST(LineFileParameter, TheResourcesComeFirstThenTheWorkingDirectory) {
    TempDir tmp;
    const fs::path resources = tmp.path / "resources", work = tmp.path / "work";
    fs::create_directories(resources);
    fs::create_directories(work);
    fs::copy_file(kChainDeck, work / "chain.dat");
    const fs::path saved = fs::current_path();
    fs::current_path(work);
    {
        const std::string uri = file_uri(resources);
        Instance inst("cwd", true, uri.c_str());
        ASSERT_EQ(inst.setString("lineFile", "chain.dat"), fmi2OK);
        set_scene(inst);
        EXPECT_EQ(inst.initialize(), fmi2OK) << inst.log.all();
        EXPECT_TRUE(inst.log.contains("lineFile " + (work / "chain.dat").string() + " read")) << inst.log.all();
    }
    fs::copy_file(kChainDeck, resources / "chain.dat");
    {
        const std::string uri = "file:" + resources.string();  // the short form file:/path
        Instance inst("resources", true, uri.c_str());
        ASSERT_EQ(inst.setString("lineFile", "chain.dat"), fmi2OK);
        set_scene(inst);
        EXPECT_EQ(inst.initialize(), fmi2OK) << inst.log.all();
        EXPECT_TRUE(inst.log.contains("lineFile " + (resources / "chain.dat").string() + " read")) << inst.log.all();
    }
    fs::current_path(saved);
}

TEST(LineFileParameter, AnAbsolutePathIsReadAsIs) {
    Instance inst;
    ASSERT_EQ(inst.setString("lineFile", kChainDeck.c_str()), fmi2OK);
    set_scene(inst);
    EXPECT_EQ(inst.initialize(), fmi2OK) << inst.log.all();
    EXPECT_TRUE(inst.log.contains("lineFile " + kChainDeck.string() + " read")) << inst.log.all();
}

TEST(LineFileParameter, AFileUriIsThePathItNames) {
    // A directory with a space: the URI percent-encodes it, the FMU reads the decoded path.
    TempDir tmp;
    const fs::path dir = tmp.path / "deck dir";
    fs::create_directory(dir);
    write_text(dir / "chain.dat", read_text(kChainDeck));
    const std::string uri = file_uri(dir / "chain.dat");
    Instance inst;
    ASSERT_EQ(inst.setString("lineFile", uri.c_str()), fmi2OK);
    set_scene(inst);
    EXPECT_EQ(inst.initialize(), fmi2OK) << inst.log.all();
    EXPECT_TRUE(inst.log.contains("lineFile " + (dir / "chain.dat").string() + " read")) << inst.log.all();
    Instance remote("remote");
    ASSERT_EQ(remote.setString("lineFile", "file://server/decks/chain.dat"), fmi2OK);
    EXPECT_EQ(remote.initialize(), fmi2Error);
    EXPECT_TRUE(remote.log.contains("tried file://server/decks/chain.dat (no such file)")) << remote.log.all();
}

TEST(LineFileParameter, AnUnreadableFileIsAnErrorNamingEveryPathTried) {
    TempDir tmp;
    const std::string uri = file_uri(tmp.path);
    Instance inst("missing", true, uri.c_str());
    ASSERT_EQ(inst.setString("lineFile", "no/such/deck.dat"), fmi2OK);
    EXPECT_EQ(inst.initialize(), fmi2Error);
    const std::string cwd = fs::current_path().string();
    EXPECT_TRUE(inst.log.contains("fmi2ExitInitializationMode: lineFile = 'no/such/deck.dat' cannot be read: tried " +
                                  (tmp.path / "no/such/deck.dat").string() + " (no such file), " + cwd +
                                  "/no/such/deck.dat (no such file)"))
        << inst.log.all();
    Instance directory("directory", true, uri.c_str());
    ASSERT_EQ(directory.setString("lineFile", tmp.path.c_str()), fmi2OK);
    EXPECT_EQ(directory.initialize(), fmi2Error);
    EXPECT_TRUE(directory.log.contains("(a directory)")) << directory.log.all();
    Instance none("none");
    ASSERT_EQ(none.setString("lineFile", "deck.dat"), fmi2OK);
    EXPECT_EQ(none.initialize(), fmi2Error);
    EXPECT_TRUE(none.log.contains("no resources directory was given to fmi2Instantiate")) << none.log.all();
}

TEST(LineFileParameter, ARefusedDeckIsAnErrorNamingTheFileAndItsLine) {
    TempDir tmp;
    std::string text = read_text(kChainDeck);
    const size_t at = text.find("1    chain     1");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 16, "1    rope      1");
    write_text(tmp.path / "bad.dat", text);
    const std::string uri = file_uri(tmp.path);
    Instance inst("bad", true, uri.c_str());
    ASSERT_EQ(inst.setString("lineFile", "bad.dat"), fmi2OK);
    EXPECT_EQ(inst.initialize(), fmi2Error);
    EXPECT_TRUE(inst.log.contains("fmi2ExitInitializationMode: lineFile " + (tmp.path / "bad.dat").string() +
                                  ", line 16: line type 'rope' is not among the LINE TYPES ('chain')"))
        << inst.log.all();
}

TEST(LineFileParameter, ParametersOutsideTheFileStillApply) {
    // A softer seabed and a looser tolerance set alongside the file act as they do on the same line
    // described by parameters; they change the result.
    Instance deck("deck", true), params("params"), stiff("stiff");
    ASSERT_EQ(deck.setString("lineFile", kChainDeck.c_str()), fmi2OK);
    ASSERT_EQ(stiff.setString("lineFile", kChainDeck.c_str()), fmi2OK);
    set_chain_by_parameters(params);
    for (Instance* inst : {&deck, &params, &stiff}) set_scene(*inst);
    for (Instance* inst : {&deck, &params}) {
        inst->setReal("seabedStiffness", 1e5);
        inst->setReal("tensionTolerance", 1e-3);
    }
    ASSERT_EQ(deck.initialize(), fmi2OK) << deck.log.all();
    ASSERT_EQ(params.initialize(), fmi2OK) << params.log.all();
    ASSERT_EQ(stiff.initialize(), fmi2OK) << stiff.log.all();
    double t1 = 0.0, t2 = 0.0, t3 = 0.0;
    ASSERT_EQ(surge(deck, 2, 0.5, &t1), fmi2OK);
    ASSERT_EQ(surge(params, 2, 0.5, &t2), fmi2OK);
    ASSERT_EQ(surge(stiff, 2, 0.5, &t3), fmi2OK);
    EXPECT_TRUE(bitwise_equal(deck.outputs(), params.outputs()));
    // The static penetration w / k is 10x deeper on the softer seabed; surging, more than twice.
    EXPECT_LT(deck.getReal("minSeabedClearance"), 2.0 * stiff.getReal("minSeabedClearance"));
}

TEST(LineFileParameter, AStateRestoresWithoutReadingTheFileAgain) {
    TempDir tmp;
    fs::copy_file(kChainDeck, tmp.path / "chain.dat");
    const std::string uri = file_uri(tmp.path);
    Instance original("original", true, uri.c_str());
    ASSERT_EQ(original.setString("lineFile", "chain.dat"), fmi2OK);
    set_scene(original);
    ASSERT_EQ(original.initialize(), fmi2OK) << original.log.all();
    double t = 0.0;
    ASSERT_EQ(surge(original, 2, 0.5, &t), fmi2OK);
    fmi2FMUstate state = nullptr;
    ASSERT_EQ(fmi().GetFMUstate(original.c, &state), fmi2OK);
    size_t size = 0;
    ASSERT_EQ(fmi().SerializedFMUstateSize(original.c, state, &size), fmi2OK);
    std::vector<fmi2Byte> bytes(size);
    ASSERT_EQ(fmi().SerializeFMUstate(original.c, state, bytes.data(), size), fmi2OK);
    fmi().FreeFMUstate(original.c, &state);
    double t1 = t;
    ASSERT_EQ(surge(original, 2, 0.5, &t1), fmi2OK);

    fs::remove(tmp.path / "chain.dat");  // the restored instance cannot read it
    Instance restored("restored");
    ASSERT_EQ(restored.setup(), fmi2OK);
    fmi2FMUstate copy = nullptr;
    ASSERT_EQ(fmi().DeSerializeFMUstate(restored.c, bytes.data(), size, &copy), fmi2OK) << restored.log.all();
    ASSERT_EQ(fmi().SetFMUstate(restored.c, copy), fmi2OK) << restored.log.all();
    fmi().FreeFMUstate(restored.c, &copy);
    EXPECT_EQ(restored.getString("lineFile"), "chain.dat");
    double t2 = t;
    ASSERT_EQ(surge(restored, 2, 0.5, &t2), fmi2OK) << restored.log.all();
    EXPECT_TRUE(bitwise_equal(original.outputs(), restored.outputs()));
}
