// SUNDIALS' own messages (IDA's errors, the text of a failure) reach the integrator's report and are never
// printed: an FMU must not write to stdout or stderr. SUNDIALS 6 hands them to an error handler, 7 to the
// context's logger, which prints errors to stderr and warnings to stdout unless routed (src/numerics/integrator.cpp).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <sundials/sundials_context.h>

#include "numerics/integrator.h"
#include "numerics/sundials_compat.h"

namespace {

using uc::Integrator;
using uc::SecondOrderSystem;

// q'' = -q, whose residual fails beyond time tFail: IDA gives up with its own message.
class Oscillator : public SecondOrderSystem {
public:
    explicit Oscillator(double tFail) : tFail_(tFail) {}
    int residual(double t, const double* y, const double* yp, double* r) override {
        if (t > tFail_) return -1;  // unrecoverable
        r[0] = yp[0] - y[1];
        r[1] = yp[1] + y[0];
        return 0;
    }
    int jacobian(double, const double*, const double*, const EntrySink& sink) override {
        sink(0, 0, 1.0, 0.0, 1.0);  // dR/dq = 1, dR/da = 1
        return 0;
    }

private:
    double tFail_;
};

struct Context {
    SUNContext ctx = nullptr;
    Context() { SUNContext_Create(UC_SUN_COMM_NULL, &ctx); }
    ~Context() { SUNContext_Free(&ctx); }
};

// Integrates the oscillator to t = 1 and captures what was printed meanwhile.
struct Outcome {
    bool ok = false;
    std::string error, out, err;
};

Outcome run(double tFail) {
    Oscillator system(tFail);
    Outcome r;
    testing::internal::CaptureStdout();
    testing::internal::CaptureStderr();
    {
        Context context;
        Integrator integrator(context.ctx, 1, 0, &system);
        const std::vector<double> atol(2, 1e-8);
        const double y[2] = {1.0, 0.0}, yp[2] = {0.0, -1.0};
        r.ok = integrator.set_tolerances(atol, 0.0, 0.0, r.error) && integrator.restart(0.0, y, yp, r.error) &&
               integrator.advance(1.0, r.error);
    }
    r.out = testing::internal::GetCapturedStdout();
    r.err = testing::internal::GetCapturedStderr();
    return r;
}

TEST(IntegratorMessages, AFailureReportsIdasOwnTextAndPrintsNothing) {
    const Outcome r = run(0.5);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("IDA_RES_FAIL"), std::string::npos) << r.error;  // the returned flag, named
    // IDA's own message (6.4 and 7.5 alike; the function named before it differs)
    EXPECT_NE(r.error.find("At t = "), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("the residual function failed unrecoverably"), std::string::npos) << r.error;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "");
}

TEST(IntegratorMessages, ASuccessfulRunPrintsNothing) {
    const Outcome r = run(10.0);
    EXPECT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, "");
}

}  // namespace
