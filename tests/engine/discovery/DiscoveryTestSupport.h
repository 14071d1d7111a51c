#pragma once
// Shared by the discovery tests: the virtual plant's data as the studies take them, and a check
// that a round and the finding it named tell the same numbers.

#include "discovery/Discovery.h"
#include "plant/PlantExport.h"
#include "plant/VirtualPlant.h"

#include <QString>
#include <QtGlobal>
#include <algorithm>

namespace drytwin::test {

/// Four batches of 3,000 s of the plant @p o describes (as study_discovery runs them).
inline std::vector<data::SiBatch> fourBatchesOf(plant::PlantOptions o) {
    o.batches = 4;
    o.samples = 3000;
    auto r = plant::runPlant(o);
    if (!r) {
        qFatal("%s", r.error().message().c_str());
    }
    return plant::toSiBatches(*r, o.seed);
}

/// Empty when each round that named a cause reports that cause's held-out numbers, as its finding
/// (or, for a look-alike folded into another finding, that finding's entry for it) does; else what
/// differs. The Discover tab shows both side by side; a round once gave the numbers of the first
/// candidate it tried, which another test then turned down.
inline QString roundsDisagreeWithFindings(const discovery::DiscoveryResult& r) {
    for (const auto& rd : r.rounds) {
        if (!rd.named) {
            continue;
        }
        double explained = -1;
        if (const auto f = std::find_if(r.findings.begin(), r.findings.end(),
                                        [&](const discovery::Finding& x) { return x.cause == rd.best; });
            f != r.findings.end()) {
            if (rd.explainedFractionFast != f->explainedFractionFast) {
                return QStringLiteral("%1: the round's fast part %2, its finding's %3")
                    .arg(QString::fromStdString(rd.best))
                    .arg(rd.explainedFractionFast)
                    .arg(f->explainedFractionFast);
            }
            explained = f->explainedFraction;
        } else {
            for (const auto& f : r.findings) {
                for (const auto& l : f.lookAlikes) {
                    if (l.namedAfter && l.cause == rd.best) {
                        explained = l.explainedAfter;
                    }
                }
            }
        }
        const std::string withdrawn = rd.best + ": named first, then withdrawn";
        if (explained < 0 && std::none_of(r.notes.begin(), r.notes.end(),
                                          [&](const std::string& n) { return n.rfind(withdrawn, 0) == 0; })) {
            return QStringLiteral("a round names %1, no finding does").arg(QString::fromStdString(rd.best));
        }
        if (explained >= 0 && rd.explainedFraction != explained) {
            return QStringLiteral("%1: the round explains %2, its finding %3")
                .arg(QString::fromStdString(rd.best))
                .arg(rd.explainedFraction)
                .arg(explained);
        }
    }
    return {};
}

} // namespace drytwin::test
