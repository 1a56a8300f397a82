#pragma once
// Chi-square goodness of fit of a sampler against its own pdf.
//
// Draw n points with the sampler, count them in the cells of a binning, and compare with the
// counts the pdf predicts, E_c = n * J * integral over cell c of pdf du dv (numerically, with
// Gauss-Kronrod quadrature from Boost.Math). Pearson's statistic
//   X^2 = sum_c (O_c - E_c)^2 / E_c  ~  chi^2(cells - 1)   if the sampler follows its pdf,
// which holds when every E_c is large enough: cells with E_c < 5 are pooled into one. A
// sample in a cell where the pdf is zero, or outside the domain, fails at once (p = 0): a
// correct sampler never puts one there. The pdf is used as it is, not normalised, so a pdf
// that claims the wrong constant (1/pi for 1/(2 pi)) is caught too.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <boost/math/quadrature/gauss_kronrod.hpp>

#include "core/rng.hpp"
#include "stats/binning.hpp"

namespace mcrt::testing {

/// Below this many expected samples a cell is pooled with the other small cells: the
/// chi-square approximation of Pearson's statistic needs E_c >= 5 (Cochran's rule).
inline constexpr double k_min_expected = 5.0;

/// A cell whose expected count is below this is a cell where the sampler must never land: a
/// sample there has probability < 1e-9 under the pdf, so it fails the test at once.
inline constexpr double k_zero_expected = 1e-9;

/// Observed and expected counts of one cell (u_index, v_index) of a Grid.
struct CellCount {
  int u_index = 0;
  int v_index = 0;
  double observed = 0.0;
  double expected = 0.0;
};

/// The outcome of a chi-square goodness-of-fit test.
struct ChiSquareResult {
  std::vector<CellCount> cells;   ///< every cell of the grid, before pooling
  std::uint64_t outside = 0;      ///< samples that fell outside the domain
  double statistic = 0.0;         ///< Pearson's X^2 over the pooled cells
  double dof = 0.0;               ///< pooled cells - 1
  double p_value = 1.0;           ///< P(chi^2(dof) > X^2); 0 after an immediate failure
  int pooled_cells = 0;           ///< cells with E_c < k_min_expected merged into one
  std::string immediate_failure;  ///< why p = 0 without a statistic, or empty

  /// One line: "X^2 = 231.4, dof = 230, p = 0.46 (3 cells pooled)" or the immediate failure.
  std::string describe() const;
};

/// Pearson's chi-square test of observed against expected counts, pooling the cells with
/// expected < min_expected (and the pool with the smallest other cell if it is still short),
/// failing at once on `outside` samples or on a sample in a zero-expected cell. Throws
/// std::invalid_argument when fewer than two cells remain.
ChiSquareResult chi_square_test(std::vector<CellCount> cells, std::uint64_t outside,
                                double min_expected = k_min_expected);

/// The probability of each cell under `pdf` (a callable double(const Point&)):
/// P_c = J * integral over the cell of pdf(point_at(u, v)) du dv, by nested adaptive
/// Gauss-Kronrod quadrature (15 points, relative tolerance 1e-10).
template <class Point, class Pdf>
std::vector<double> cell_probabilities(const Pdf& pdf, const Binning<Point>& binning) {
  using Quadrature = boost::math::quadrature::gauss_kronrod<double, 15>;
  constexpr unsigned k_max_depth = 6;  // 64 sub-intervals: ample for pdfs smooth in a cell
  constexpr double k_tolerance = 1e-10;
  std::vector<double> probability(static_cast<std::size_t>(binning.cell_count()));
  for (int j = 0; j < binning.v_cells; ++j)
    for (int i = 0; i < binning.u_cells; ++i) {
      const double u0 = binning.u_low(i), u1 = u0 + binning.u_width();
      const double v0 = binning.v_low(j), v1 = v0 + binning.v_width();
      const auto along_u = [&](double v) {
        const auto f = [&](double u) { return static_cast<double>(pdf(binning.point_at(u, v))); };
        return Quadrature::integrate(f, u0, u1, k_max_depth, k_tolerance);
      };
      probability[static_cast<std::size_t>(j * binning.u_cells + i)] =
          binning.jacobian * Quadrature::integrate(along_u, v0, v1, k_max_depth, k_tolerance);
    }
  return probability;
}

/// The integral of `pdf` over the binning's whole domain: 1 for a pdf (up to quadrature error).
template <class Point, class Pdf>
double pdf_integral(const Pdf& pdf, const Binning<Point>& binning) {
  double total = 0.0;
  for (double p : cell_probabilities(pdf, binning)) total += p;
  return total;
}

/// Counts `points` in the cells of `binning` and tests the counts against the cell
/// probabilities `probability` (cell_probabilities of the pdf).
template <class Point>
ChiSquareResult chi_square_points_test(const std::vector<Point>& points,
                                       const std::vector<double>& probability,
                                       const Binning<Point>& binning) {
  std::vector<CellCount> cells(probability.size());
  for (std::size_t c = 0; c < cells.size(); ++c) {
    cells[c].u_index = static_cast<int>(c) % binning.u_cells;
    cells[c].v_index = static_cast<int>(c) / binning.u_cells;
    cells[c].expected = static_cast<double>(points.size()) * probability[c];
  }
  std::uint64_t outside = 0;
  for (const Point& p : points) {
    const int c = binning.cell_of(p);
    if (c < 0)
      ++outside;
    else
      cells[static_cast<std::size_t>(c)].observed += 1.0;
  }
  return chi_square_test(std::move(cells), outside);
}

/// Draws `samples` points sample(u) with u from Rng(seed, stream) and tests their counts in
/// `binning` against `pdf`. Sampler: Point(Vec2 u); Pdf: double(const Point&).
template <class Point, class Sampler, class Pdf>
ChiSquareResult chi_square_sampler_test(const Sampler& sample, const Pdf& pdf,
                                        const Binning<Point>& binning, std::uint64_t seed,
                                        std::uint64_t samples, std::uint64_t stream = 0) {
  Rng rng(seed, stream);
  std::vector<Point> points;
  points.reserve(samples);
  for (std::uint64_t k = 0; k < samples; ++k) points.push_back(sample(rng.uniform2()));
  return chi_square_points_test(points, cell_probabilities(pdf, binning), binning);
}

/// Writes the failure report of a chi-square test into `dir`: NAME.csv (one row per cell:
/// u_index, v_index, u_low, u_high, v_low, v_high, observed, expected, residual =
/// (O - E) / sqrt(E)) and NAME.gp with its PNG/SVG heat map of the residuals (via
/// mcrt::write_plot). Returns the CSV's path. Throws mcrt::IoError if it cannot write.
std::filesystem::path write_chi_square_report(const std::filesystem::path& dir,
                                              const std::string& name,
                                              const ChiSquareResult& result, const Grid& grid);

/// How to run a sampler's chi-square test.
struct SamplerTest {
  std::string name;                ///< names the report files
  std::uint64_t samples = 100000;  ///< points drawn
  std::uint64_t stream = 0;        ///< generator stream (with the seed)
  double alpha = 1e-4;             ///< below this p-value the test fails and reports
};

/// Reports a failed test: writes its CSV and plot under failure_report_root()/test.name/
/// (when reports are on) and prints their paths on stderr.
void report_chi_square_failure(const SamplerTest& test, const ChiSquareResult& result,
                               const Grid& grid);

/// The p-value of the chi-square test of a sampler against its pdf; on p < test.alpha also
/// writes the failure report.
template <class Point, class Sampler, class Pdf>
double chi_square_sampler_p_value(const Sampler& sample, const Pdf& pdf,
                                  const Binning<Point>& binning, std::uint64_t seed,
                                  const SamplerTest& test) {
  const ChiSquareResult result =
      chi_square_sampler_test(sample, pdf, binning, seed, test.samples, test.stream);
  if (result.p_value < test.alpha) report_chi_square_failure(test, result, binning);
  return result.p_value;
}

}  // namespace mcrt::testing
