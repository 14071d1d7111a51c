#include "physics/FastVectorKernels.h"

#include <nvector/nvector_serial.h>

#include <Eigen/Core>

#include <cmath>

namespace drytwin::physics {

namespace {

using Array = Eigen::Map<Eigen::ArrayXd>;

Array arr(N_Vector v) {
    return {NV_DATA_S(v), static_cast<Eigen::Index>(NV_LENGTH_S(v))};
}

void linearSum(sunrealtype a, N_Vector x, sunrealtype b, N_Vector y, N_Vector z) {
    arr(z) = a * arr(x) + b * arr(y);
}
void constant(sunrealtype c, N_Vector z) {
    arr(z).setConstant(c);
}
void prod(N_Vector x, N_Vector y, N_Vector z) {
    arr(z) = arr(x) * arr(y);
}
void div(N_Vector x, N_Vector y, N_Vector z) {
    arr(z) = arr(x) / arr(y);
}
void scale(sunrealtype c, N_Vector x, N_Vector z) {
    arr(z) = c * arr(x);
}
void absolute(N_Vector x, N_Vector z) {
    arr(z) = arr(x).abs();
}
void inv(N_Vector x, N_Vector z) {
    arr(z) = arr(x).inverse();
}
void addConst(N_Vector x, sunrealtype b, N_Vector z) {
    arr(z) = arr(x) + b;
}
sunrealtype dotProd(N_Vector x, N_Vector y) {
    return (arr(x) * arr(y)).sum();
}
sunrealtype maxNorm(N_Vector x) {
    return NV_LENGTH_S(x) > 0 ? arr(x).abs().maxCoeff() : 0.0;
}
sunrealtype wSqrSum(N_Vector x, N_Vector w) {
    return (arr(x) * arr(w)).square().sum();
}
sunrealtype wSqrSumMask(N_Vector x, N_Vector w, N_Vector id) {
    return ((arr(id) > 0).cast<double>() * (arr(x) * arr(w)).square()).sum();
}
sunrealtype wrmsNorm(N_Vector x, N_Vector w) {
    return std::sqrt(wSqrSum(x, w) / static_cast<double>(NV_LENGTH_S(x)));
}
sunrealtype wrmsNormMask(N_Vector x, N_Vector w, N_Vector id) {
    return std::sqrt(wSqrSumMask(x, w, id) / static_cast<double>(NV_LENGTH_S(x)));
}
sunrealtype minimum(N_Vector x) {
    return NV_LENGTH_S(x) > 0 ? arr(x).minCoeff() : SUN_BIG_REAL;
}
sunrealtype wl2Norm(N_Vector x, N_Vector w) {
    return std::sqrt(wSqrSum(x, w));
}
sunrealtype l1Norm(N_Vector x) {
    return arr(x).abs().sum();
}
void compare(sunrealtype c, N_Vector x, N_Vector z) {
    arr(z) = (arr(x).abs() >= c).cast<double>();
}
sunbooleantype invTest(N_Vector x, N_Vector z) {
    // z = 1/x where x ≠ 0; false when some x is 0 (those z are left alone), as N_VInvTest_Serial.
    const double* xd = NV_DATA_S(x);
    double* zd = NV_DATA_S(z);
    sunbooleantype noZero = SUNTRUE;
    for (sunindextype i = 0; i < NV_LENGTH_S(x); ++i) {
        if (xd[i] == 0.0) {
            noZero = SUNFALSE;
        } else {
            zd[i] = 1.0 / xd[i];
        }
    }
    return noZero;
}
sunrealtype minQuotient(N_Vector num, N_Vector denom) {
    const double* n = NV_DATA_S(num);
    const double* d = NV_DATA_S(denom);
    double m = SUN_BIG_REAL;
    for (sunindextype i = 0; i < NV_LENGTH_S(num); ++i) {
        if (d[i] != 0.0) {
            m = std::min(m, n[i] / d[i]);
        }
    }
    return m;
}

int linearCombination(int nvec, sunrealtype* c, N_Vector* x, N_Vector z) {
    // z may be x[0] (SUNDIALS allows it): scale it in place first, then accumulate.
    if (x[0] == z) {
        if (c[0] != 1.0) {
            arr(z) *= c[0];
        }
    } else {
        arr(z) = c[0] * arr(x[0]);
    }
    for (int j = 1; j < nvec; ++j) {
        arr(z) += c[j] * arr(x[j]);
    }
    return 0;
}
int scaleAddMulti(int nvec, sunrealtype* a, N_Vector x, N_Vector* y, N_Vector* z) {
    for (int j = 0; j < nvec; ++j) {
        arr(z[j]) = a[j] * arr(x) + arr(y[j]);
    }
    return 0;
}
int dotProdMulti(int nvec, N_Vector x, N_Vector* y, sunrealtype* d) {
    for (int j = 0; j < nvec; ++j) {
        d[j] = dotProd(x, y[j]);
    }
    return 0;
}
int linearSumArray(int nvec, sunrealtype a, N_Vector* x, sunrealtype b, N_Vector* y, N_Vector* z) {
    for (int j = 0; j < nvec; ++j) {
        linearSum(a, x[j], b, y[j], z[j]);
    }
    return 0;
}
int scaleArray(int nvec, sunrealtype* c, N_Vector* x, N_Vector* z) {
    for (int j = 0; j < nvec; ++j) {
        scale(c[j], x[j], z[j]);
    }
    return 0;
}
int constArray(int nvec, sunrealtype c, N_Vector* z) {
    for (int j = 0; j < nvec; ++j) {
        constant(c, z[j]);
    }
    return 0;
}
int wrmsNormArray(int nvec, N_Vector* x, N_Vector* w, sunrealtype* nrm) {
    for (int j = 0; j < nvec; ++j) {
        nrm[j] = wrmsNorm(x[j], w[j]);
    }
    return 0;
}

} // namespace

void useFastVectorKernels(N_Vector v) {
    N_Vector_Ops ops = v->ops;
    ops->nvlinearsum = linearSum;
    ops->nvconst = constant;
    ops->nvprod = prod;
    ops->nvdiv = div;
    ops->nvscale = scale;
    ops->nvabs = absolute;
    ops->nvinv = inv;
    ops->nvaddconst = addConst;
    ops->nvdotprod = dotProd;
    ops->nvmaxnorm = maxNorm;
    ops->nvwrmsnorm = wrmsNorm;
    ops->nvwrmsnormmask = wrmsNormMask;
    ops->nvmin = minimum;
    ops->nvwl2norm = wl2Norm;
    ops->nvl1norm = l1Norm;
    ops->nvcompare = compare;
    ops->nvinvtest = invTest;
    ops->nvminquotient = minQuotient;
    // Fused operations: one call instead of a loop of linear sums in CVODE's Nordsieck updates.
    ops->nvlinearcombination = linearCombination;
    ops->nvscaleaddmulti = scaleAddMulti;
    ops->nvdotprodmulti = dotProdMulti;
    ops->nvlinearsumvectorarray = linearSumArray;
    ops->nvscalevectorarray = scaleArray;
    ops->nvconstvectorarray = constArray;
    ops->nvwrmsnormvectorarray = wrmsNormArray;
    // Local reductions (used by the generic layer and the nonlinear solvers).
    ops->nvdotprodlocal = dotProd;
    ops->nvmaxnormlocal = maxNorm;
    ops->nvminlocal = minimum;
    ops->nvl1normlocal = l1Norm;
    ops->nvinvtestlocal = invTest;
    ops->nvminquotientlocal = minQuotient;
    ops->nvwsqrsumlocal = wSqrSum;
    ops->nvwsqrsummasklocal = wSqrSumMask;
}

} // namespace drytwin::physics
