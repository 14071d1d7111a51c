#include "physics/BatchedIntegrator.h"

#include "physics/FastVectorKernels.h"

#include <cvodes/cvodes.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <cstdlib>
#include <memory>

namespace drytwin::physics {

namespace {

struct SystemData {
    const ParcelRhs* rhs = nullptr;
    std::size_t first = 0; ///< first parcel of this system
    std::size_t count = 0; ///< parcels in this system
};

int cvRhs(sunrealtype s, N_Vector y, N_Vector ydot, void* user) {
    const auto* d = static_cast<const SystemData*>(user);
    const double* yv = N_VGetArrayPointer(y);
    double* dv = N_VGetArrayPointer(ydot);
    // false: recoverable, CVODE retries with a smaller step
    return d->rhs->evaluate(d->rhs->context, s, d->first, d->count, yv, dv) ? 0 : 1;
}

void silentErrors(int, const char*, const char*, char*, void*) {}

/// Owns every SUNDIALS object of one solve.
struct Solver {
    SUNContext ctx = nullptr;
    void* mem = nullptr;
    N_Vector y = nullptr;
    N_Vector abstol = nullptr;
    N_Vector* yS = nullptr;
    int ns = 0;
    SUNNonlinearSolver nls = nullptr;
    SUNNonlinearSolver nlsSens = nullptr;
    SUNMatrix a = nullptr;
    SUNLinearSolver ls = nullptr;
    ~Solver() {
        if (mem) {
            CVodeFree(&mem);
        }
        if (nls) {
            SUNNonlinSolFree(nls);
        }
        if (nlsSens) {
            SUNNonlinSolFree(nlsSens);
        }
        if (ls) {
            SUNLinSolFree(ls);
        }
        if (a) {
            SUNMatDestroy(a);
        }
        if (yS) {
            N_VDestroyVectorArray(yS, ns);
        }
        if (abstol) {
            N_VDestroy(abstol);
        }
        if (y) {
            N_VDestroy(y);
        }
        if (ctx) {
            SUNContext_Free(&ctx);
        }
    }
};

Status solveSystem(const ParcelRhs& rhs, std::size_t first, std::size_t count, double* yData, double duration,
                   const IntegratorSettings& settings, const SensitivitySpec* sens,
                   std::vector<std::vector<double>>* ySData, const std::string& section,
                   IntegratorStats* stats) {
    const auto m = static_cast<std::size_t>(rhs.statesPerParcel);
    const auto n = static_cast<sunindextype>(count * m);
    Solver s;
    auto fail = [&](const std::string& what, int flag) {
        // CVodeGetReturnFlagName hands over a malloc'd string.
        char* name = CVodeGetReturnFlagName(flag);
        const std::string flagName = name ? name : "unknown flag";
        std::free(name);
        return Status(Error{ErrorKind::Numerical, section, what + " failed (" + flagName + ")"});
    };
    if (SUNContext_Create(nullptr, &s.ctx) != 0) {
        return Error{ErrorKind::Numerical, section, "could not create a SUNDIALS context"};
    }
    s.y = N_VNew_Serial(n, s.ctx);
    s.abstol = N_VNew_Serial(n, s.ctx);
    if (!s.y || !s.abstol) {
        return Error{ErrorKind::Numerical, section, "could not allocate the solver's vectors"};
    }
    // Every vector CVODE clones from these inherits the optimised kernels.
    useFastVectorKernels(s.y);
    useFastVectorKernels(s.abstol);
    double* yv = N_VGetArrayPointer(s.y);
    double* at = N_VGetArrayPointer(s.abstol);
    for (std::size_t i = 0; i < count * m; ++i) {
        yv[i] = yData[i];
        at[i] = settings.absTol.empty() ? settings.relTol : settings.absTol[i % m];
    }
    SystemData data{&rhs, first, count};
    s.mem = CVodeCreate(settings.reference ? CV_BDF : CV_ADAMS, s.ctx);
    CVodeSetErrHandlerFn(s.mem, silentErrors, nullptr);
    int flag = CVodeInit(s.mem, cvRhs, 0.0, s.y);
    if (flag < 0) {
        return fail("CVodeInit", flag);
    }
    CVodeSVtolerances(s.mem, settings.relTol, s.abstol);
    CVodeSetUserData(s.mem, &data);
    CVodeSetMaxNumSteps(s.mem, settings.maxSteps);
    if (!settings.reference) {
        // Each Adams order adds a Nordsieck vector that every step updates; the sections run at
        // order 2–4 anyway (the inputs' kinks every sample keep the order low).
        CVodeSetMaxOrd(s.mem, settings.maxAdamsOrder);
        CVodeSetNonlinConvCoef(s.mem, settings.nonlinearConvergenceCoefficient);
    }
    CVodeSetStopTime(s.mem, duration);
    if (settings.reference) {
        s.a = SUNDenseMatrix(n, n, s.ctx);
        s.ls = SUNLinSol_Dense(s.y, s.a, s.ctx);
        CVodeSetLinearSolver(s.mem, s.ls, s.a);
    } else {
        s.nls = SUNNonlinSol_FixedPoint(s.y, 0, s.ctx);
        CVodeSetNonlinearSolver(s.mem, s.nls);
    }
    if (sens && ySData) {
        s.ns = static_cast<int>(sens->plist.size());
        s.yS = N_VCloneVectorArray(s.ns, s.y);
        for (int j = 0; j < s.ns; ++j) {
            double* d = N_VGetArrayPointer(s.yS[j]);
            for (std::size_t i = 0; i < count * m; ++i) {
                d[i] = (*ySData)[static_cast<std::size_t>(j)][first * m + i];
            }
        }
        flag = CVodeSensInit(s.mem, s.ns, settings.reference ? CV_SIMULTANEOUS : CV_STAGGERED, nullptr, s.yS);
        if (flag < 0) {
            return fail("CVodeSensInit", flag);
        }
        CVodeSetSensParams(s.mem, sens->params, const_cast<double*>(sens->pbar.data()),
                           const_cast<int*>(sens->plist.data()));
        CVodeSensEEtolerances(s.mem);
        CVodeSetSensErrCon(s.mem, SUNTRUE);
        if (!settings.reference) {
            s.nlsSens = SUNNonlinSol_FixedPointSens(s.ns, s.y, 0, s.ctx);
            CVodeSetNonlinearSolverSensStg(s.mem, s.nlsSens);
        }
    }
    sunrealtype t = 0;
    flag = CVode(s.mem, duration, s.y, &t, CV_NORMAL);
    if (flag < 0) {
        return fail("integration to " + std::to_string(duration) + " s", flag);
    }
    for (std::size_t i = 0; i < count * m; ++i) {
        yData[i] = yv[i];
    }
    if (s.ns > 0) {
        CVodeGetSens(s.mem, &t, s.yS);
        for (int j = 0; j < s.ns; ++j) {
            const double* d = N_VGetArrayPointer(s.yS[j]);
            for (std::size_t i = 0; i < count * m; ++i) {
                (*ySData)[static_cast<std::size_t>(j)][first * m + i] = d[i];
            }
        }
    }
    if (stats) {
        long steps = 0;
        long fevals = 0;
        CVodeGetNumSteps(s.mem, &steps);
        CVodeGetNumRhsEvals(s.mem, &fevals);
        stats->steps += steps;
        stats->rhsEvaluations += fevals * static_cast<long>(count);
    }
    return {};
}

} // namespace

Status integrateParcels(const ParcelRhs& rhs, std::vector<double>& y, double duration,
                        const IntegratorSettings& settings, const SensitivitySpec* sens,
                        std::vector<std::vector<double>>* yS, const std::string& section,
                        IntegratorStats* stats) {
    if (rhs.parcels == 0 || duration <= 0) {
        return {};
    }
    const auto m = static_cast<std::size_t>(rhs.statesPerParcel);
    if (!settings.reference) {
        return solveSystem(rhs, 0, rhs.parcels, y.data(), duration, settings, sens, yS, section, stats);
    }
    for (std::size_t i = 0; i < rhs.parcels; ++i) {
        if (auto st = solveSystem(rhs, i, 1, y.data() + i * m, duration, settings, sens, yS,
                                  section + " (parcel " + std::to_string(i) + ")", stats);
            !st) {
            return st;
        }
    }
    return {};
}

} // namespace drytwin::physics
