#include "stats/chi_square.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "io/output.hpp"
#include "io/plot.hpp"
#include "stats/hypothesis.hpp"
#include "stats/report.hpp"

namespace mcrt::testing {

namespace fs = std::filesystem;

std::string ChiSquareResult::describe() const {
  std::ostringstream s;
  if (!immediate_failure.empty()) {
    s << "immediate failure: " << immediate_failure;
    return s.str();
  }
  s << "X^2 = " << statistic << ", dof = " << dof << ", p = " << p_value;
  if (pooled_cells > 0) s << " (" << pooled_cells << " cells with E < 5 pooled)";
  return s.str();
}

ChiSquareResult chi_square_test(std::vector<CellCount> cells, std::uint64_t outside,
                                double min_expected) {
  ChiSquareResult result;
  result.cells = std::move(cells);
  result.outside = outside;
  auto fail_at_once = [&](std::string why) {
    result.immediate_failure = std::move(why);
    result.p_value = 0.0;
    return result;
  };
  if (outside > 0) return fail_at_once(std::to_string(outside) + " samples outside the domain");
  for (const CellCount& c : result.cells)
    if (c.expected < k_zero_expected && c.observed > 0.0)
      return fail_at_once(std::to_string(static_cast<long long>(c.observed)) +
                          " samples in cell (" + std::to_string(c.u_index) + ", " +
                          std::to_string(c.v_index) + ") where the pdf is zero");

  // Cells in increasing expected count; zero-expected cells (empty, checked above) carry no
  // information and are left out.
  std::vector<const CellCount*> order;
  for (const CellCount& c : result.cells)
    if (c.expected >= k_zero_expected) order.push_back(&c);
  std::sort(order.begin(), order.end(),
            [](const CellCount* a, const CellCount* b) { return a->expected < b->expected; });

  // Pool the small cells; if the pool is itself still small, merge it into the next cell.
  std::vector<std::pair<double, double>> bins;  // (observed, expected)
  double pool_observed = 0.0, pool_expected = 0.0;
  std::size_t k = 0;
  for (; k < order.size() && order[k]->expected < min_expected; ++k) {
    pool_observed += order[k]->observed;
    pool_expected += order[k]->expected;
    ++result.pooled_cells;
  }
  if (result.pooled_cells > 0 && pool_expected < min_expected && k < order.size()) {
    pool_observed += order[k]->observed;
    pool_expected += order[k]->expected;
    ++k;
  }
  if (result.pooled_cells > 0) bins.emplace_back(pool_observed, pool_expected);
  for (; k < order.size(); ++k) bins.emplace_back(order[k]->observed, order[k]->expected);
  if (bins.size() < 2)
    throw std::invalid_argument("chi-square test: fewer than 2 cells with expected count >= " +
                                std::to_string(min_expected) + "; draw more samples");

  for (const auto& [observed, expected] : bins)
    result.statistic += (observed - expected) * (observed - expected) / expected;
  result.dof = static_cast<double>(bins.size() - 1);
  result.p_value = chi_square_upper_tail(result.statistic, result.dof);
  return result;
}

fs::path write_chi_square_report(const fs::path& dir, const std::string& name,
                                 const ChiSquareResult& result, const Grid& grid) {
  prepare_output_dir(dir);
  std::ostringstream csv;
  csv.precision(10);
  csv << "u_index,v_index,u_low,u_high,v_low,v_high,observed,expected,residual\n";
  double largest = 1.0;
  for (const CellCount& c : result.cells) {
    // Standardised residual (O - E) / sqrt(E): about N(0, 1) per cell for a right sampler.
    const double residual = c.expected >= k_zero_expected
                                ? (c.observed - c.expected) / std::sqrt(c.expected)
                                : (c.observed > 0.0 ? 1e3 : 0.0);
    largest = std::max(largest, std::abs(residual));
    csv << c.u_index << ',' << c.v_index << ',' << grid.u_low(c.u_index) << ','
        << grid.u_low(c.u_index) + grid.u_width() << ',' << grid.v_low(c.v_index) << ','
        << grid.v_low(c.v_index) + grid.v_width() << ',' << c.observed << ',' << c.expected << ','
        << residual << '\n';
  }
  const fs::path csv_path = dir / (name + ".csv");
  write_file_atomic(csv_path, csv.str());

  Plot plot;
  plot.name = name;
  plot.title = name + ": " + result.describe() +
               (result.outside > 0 ? "; " + std::to_string(result.outside) + " outside" : "");
  plot.x_label = grid.u_label;
  plot.y_label = grid.v_label;
  std::ostringstream settings;
  settings << "set key off\n"
           << "set xrange [" << grid.u_min << ":" << grid.u_max << "]\n"
           << "set yrange [" << grid.v_min << ":" << grid.v_max << "]\n"
           << "set cbrange [" << -largest << ":" << largest << "]\n"
           << "set cblabel '(observed - expected) / sqrt(expected): red too many, blue too few'\n"
           << "set palette defined (-1 '#2166ac', 0 '#f7f7f7', 1 '#b2182b')\n";
  plot.settings = settings.str();
  // Cell centres as the image's pixel centres. write_plot's `set datafile columnheaders`
  // already takes the CSV's header row as names: a `skip 1` here would drop the first cell too,
  // which breaks the image's grid (no map for the hemisphere, stripes for the disk).
  plot.plot = "plot '" + name + ".csv' using (($3+$4)/2):(($5+$6)/2):9 with image";
  write_plot(dir, plot);
  return csv_path;
}

void report_chi_square_failure(const SamplerTest& test, const ChiSquareResult& result,
                               const Grid& grid) {
  if (!failure_reports_enabled()) return;
  const fs::path dir = failure_report_root() / test.name;
  try {
    const fs::path csv = write_chi_square_report(dir, test.name, result, grid);
    std::cerr << "chi-square test " << test.name << " failed (" << result.describe()
              << "): observed and expected counts per cell in " << csv.string()
              << ", residual heat map in " << (dir / (test.name + ".png")).string() << "\n";
  } catch (const IoError& e) {
    std::cerr << "chi-square test " << test.name << " failed (" << result.describe()
              << "); its report could not be written: " << e.what() << "\n";
  }
}

}  // namespace mcrt::testing
