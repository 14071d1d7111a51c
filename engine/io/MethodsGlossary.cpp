#include "io/MethodsGlossary.h"

namespace drytwin::io {

const std::vector<MethodTerm>& methodsGlossary() {
    static const std::vector<MethodTerm> terms{
        {"a global search, then a local polish that needs no derivatives", "Calibrate",
         "NLopt's CRS2-LM (controlled random search with local mutation), then BOBYQA (bound-constrained "
         "quadratic approximation)"},
        {"Standard error", "Calibrate",
         "Fisher SE: the estimate's standard error from the loss's curvature (the Fisher information)"},
        {"intervals widened because neighbouring rows are alike", "Calibrate",
         "sandwich covariance with a Newey-West middle term (autocorrelation-consistent)"},
        {"skill", "Residual model",
         "the model's MAE over that of the better of two reference forecasts: the last measurement held "
         "(persistence) and the physics model with its last error held"},
        {"How strong the evidence is", "Discover",
         "Score z: the score test's statistic for the cause's parameter at its base value, in standard "
         "deviations; against a reference period, Change z: the change of its one-step estimate from the "
         "reference's normal value"},
        {"Chance it is noise", "Discover",
         "p (Holm): the score test's p-value corrected for testing every candidate at once by Holm's "
         "step-down method; a timing cause's may come from its own score test"},
        {"the chance that a gain this large is luck", "Discover",
         "the Diebold-Mariano test of the held-out errors before and after the cause is added"},
    };
    return terms;
}

std::string methodsAppendixMarkdown() {
    std::string md = "\n## Appendix: the methods behind the workbench's words\n\n"
                     "The workbench says these in plain words; this is what each one computes.\n\n"
                     "| on screen | tab | method |\n| --- | --- | --- |\n";
    for (const auto& t : methodsGlossary()) {
        md += "| " + t.onScreen + " | " + t.where + " | " + t.method + " |\n";
    }
    return md;
}

} // namespace drytwin::io
