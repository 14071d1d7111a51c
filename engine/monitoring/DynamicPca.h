#pragma once

#include "common/Error.h"

#include <Eigen/Dense>
#include <limits>
#include <string>
#include <vector>

namespace drytwin::monitoring {

/// A block or statistic with no value (a gap in the data, a window not yet full).
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// @brief How a dynamic PCA monitor preprocesses and sizes itself.
struct DynamicPcaOptions {
    double blockS = 10;             ///< block-mean length [s]; equal to the sampling step: no averaging
    int lags = 3;                   ///< blocks per lagged row: t, t−1, … t−lags+1
    double varianceExplained = 0.9; ///< smallest share of variance the kept components reach
    double confidence = 0.99;       ///< level of the T² and SPE limits

    /// @brief An InvalidOption error naming the first bad field, or success.
    Status validate() const;
};

/// @brief Index of the block a sample @p sinceStartS after its run's first sample falls in.
/// Shared by batch and streaming so both cut blocks at the same instants.
int blockIndexOf(double sinceStartS, double blockS);

/// @brief The mean of one block's finite samples of one column, a one-sample transmitter spike
/// left out: the sample furthest from the others is dropped when it lies more than 10 of their
/// standard deviations from their mean (blocks of 4 samples or more). A single spike of 8 K in a
/// 10 s block would move a plain mean by 0.8 K, more than the noise a monitor is commissioned on,
/// and raise an alarm no process change caused. NaN when no sample is finite. @p samples loses
/// its non-finite values.
double robustBlockMean(std::vector<double>& samples);

/// @brief One run's block means (robustBlockMean), lag-embedded: row b = [x_b, x_{b−1}, …] (lag-major), NaN
/// where a block of any lag has no valid value (and in the first lags−1 rows).
Eigen::MatrixXd lagBlocks(const std::vector<double>& timeS, const Eigen::MatrixXd& values, double blockS,
                          int lags);

/// @brief log of a block T² or SPE, floored so that an exact 0 cannot become −∞.
double logStatistic(double statistic);

/// @brief Mean of a window's block log-statistics, NaN unless at least half its blocks are valid.
double windowLogMean(double sumLog, int validBlocks, int blocksPerWindow);

/// @brief Window means (windowLogMean) of one run's block log T² and log SPE over consecutive
/// windows of @p blocksPerWindow blocks; an incomplete last window is left out.
void windowLogMeans(const Eigen::VectorXd& blockLogT2, const Eigen::VectorXd& blockLogSpe,
                    int blocksPerWindow, std::vector<double>& logT2, std::vector<double>& logSpe);

/// @brief Count, mean and centred scatter of a set of complete lagged rows; combining two is
/// exact (Chan's update), which makes leave-one-out refits cheap and stable.
struct LaggedMoments {
    double count = 0;
    Eigen::VectorXd mean;
    Eigen::MatrixXd scatter; ///< Σ (x − mean)(x − mean)ᵀ

    /// @brief Moments of the rows of @p lagged without a NaN.
    static LaggedMoments of(const Eigen::MatrixXd& lagged);
    /// @brief Adds another set of rows' moments to these.
    void add(const LaggedMoments& other);
};

/// @brief One row's breakdown of T² and SPE per original column (its lags summed).
struct RowContributions {
    Eigen::VectorXd t2;  ///< complete decomposition x_j (P Λ⁻¹ Pᵀ x)_j: sums to T² (terms may be < 0)
    Eigen::VectorXd spe; ///< squared residuals: sums to SPE
    /// Reconstruction-based (Alcala & Qin 2009): how much T² falls when column j's lags are
    /// corrected as well as possible. Each is ≤ T²; they do not sum to it.
    Eigen::VectorXd t2Reconstruction;
    /// The same for SPE. Unlike the squared residuals it does not smear a fault in one column
    /// onto the columns the model ties it to, so it ranks the faulty column first.
    Eigen::VectorXd speReconstruction;
};

/// @brief T², SPE and their per-original-column contributions for each lagged row; NaN where
/// the row is incomplete. Rows of the contribution matrices are RowContributions.
struct PcaScores {
    Eigen::VectorXd t2;
    Eigen::VectorXd spe;
    Eigen::MatrixXd t2Contributions;   ///< rows × original columns; rows sum to t2
    Eigen::MatrixXd speContributions;  ///< rows × original columns; rows sum to spe
    Eigen::MatrixXd t2Reconstruction;  ///< rows × original columns
    Eigen::MatrixXd speReconstruction; ///< rows × original columns
};

/// @brief A PCA on standardised lagged block means: the model of a healthy reference.
/// Immutable once fitted; const members are safe to call from several threads.
class DynamicPca {
public:
    /// @brief Fits on the summed moments of reference runs' lagged rows. @p originalColumns is
    /// the number of columns before lagging; @p place names the call in errors.
    static Expected<DynamicPca> fit(const std::vector<LaggedMoments>& runs, int originalColumns,
                                    const DynamicPcaOptions& options, const std::string& place = "pca.fit");

    /// @brief Fits on lagged matrices (lagBlocks() output) directly.
    static Expected<DynamicPca> fit(const std::vector<Eigen::MatrixXd>& laggedRuns, int originalColumns,
                                    const DynamicPcaOptions& options, const std::string& place = "pca.fit");

    /// @brief T² and SPE of one lagged row (NaN when incomplete); contributions on request.
    void scoreRow(const Eigen::Ref<const Eigen::VectorXd>& lagged, double& t2, double& spe,
                  RowContributions* contributions = nullptr) const;
    /// @brief Scores every row of a lagged matrix.
    PcaScores score(const Eigen::MatrixXd& lagged) const;

    /// @brief Theoretical T² limit a(n−1)(n+1)/(n(n−a)) F_{a,n−a} at the fitted confidence.
    double t2Limit() const { return m_t2Limit; }
    /// @brief Theoretical SPE limit g χ²_h (Box) over the discarded eigenvalues.
    double speLimit() const { return m_speLimit; }
    /// @brief Number of kept components a.
    int components() const { return m_components; }
    /// @brief Share of the standardised variance the kept components explain.
    double varianceExplained() const { return m_varianceExplained; }
    /// @brief Number of complete lagged rows the fit used.
    double rowsUsed() const { return m_rows; }
    /// @brief Eigenvalues of the correlation matrix, largest first.
    const Eigen::VectorXd& eigenvalues() const { return m_eigenvalues; }
    /// @brief Loadings of the kept components (lagged columns × a).
    const Eigen::MatrixXd& loadings() const { return m_loadings; }
    /// @brief Reference mean of each lagged column.
    const Eigen::VectorXd& mean() const { return m_mean; }
    /// @brief Reference SD of each lagged column, 1 where the column was constant.
    const Eigen::VectorXd& scale() const { return m_scale; }
    /// @brief Lagged column indices whose SD was floored because they were constant.
    const std::vector<int>& constantColumns() const { return m_constantColumns; }
    /// @brief Columns before lagging.
    int originalColumns() const { return m_originalColumns; }
    /// @brief The options it was fitted with.
    const DynamicPcaOptions& options() const { return m_options; }

private:
    DynamicPcaOptions m_options;
    int m_originalColumns = 0;
    double m_rows = 0;
    Eigen::VectorXd m_mean, m_scale, m_eigenvalues, m_keptEigenvalues;
    Eigen::MatrixXd m_loadings;
    std::vector<Eigen::MatrixXd> m_speReconstruction,
        m_t2Reconstruction; ///< per column: (Ξᵀ M Ξ)⁺, lags × lags
    std::vector<int> m_constantColumns;
    int m_components = 0;
    double m_varianceExplained = 0;
    double m_t2Limit = 0, m_speLimit = 0;
};

} // namespace drytwin::monitoring
