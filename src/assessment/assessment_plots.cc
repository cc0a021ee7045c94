#include <assessment/assessment_files.h>
#include <assessment/assessment_plots.h>
#include <fmt/format.h>

#include <algorithm>
#include <numeric>

namespace FloorBlock::Assessment
{
  namespace
  {
    /** The FEM cases' FS against input @p i: training, then held out. */
    std::string
    case_data(const AssessmentResult &result, const std::size_t i)
    {
      std::string data;
      for (const auto *cases : {&result.training, &result.validation})
        {
          data += fmt::format("${}_{} << EOD\n",
                              cases == &result.training ? "training" : "held",
                              i);
          for (const SafetyCase &c : *cases)
            if (c.solved())
              data +=
                fmt::format("{:.9e} {:.9e}\n", c.inputs[i], c.safety_factor);
          data += "EOD\n";
        }
      return data;
    }

    /** gnuplot's string quoting: a title in double quotes. */
    std::string
    quoted(const std::string &text)
    {
      std::string out = "\"";
      for (const char c : text)
        out += c == '"' ? std::string("\\\"") : std::string(1, c);
      return out + "\"";
    }
  } // namespace

  std::string
  safety_factor_distribution_plot(const AssessmentResult &result)
  {
    std::vector<double> fs = result.surrogate_fs_sample;
    std::sort(fs.begin(), fs.end());
    std::string data = "$fs << EOD\n";
    for (const double value : fs)
      data += fmt::format("{:.6e}\n", value);
    data += "EOD\n$cdf << EOD\n";
    // 400 points of the sorted sample draw the CDF.
    const std::size_t step = std::max<std::size_t>(1, fs.size() / 400);
    for (std::size_t k = 0; k < fs.size(); k += step)
      data += fmt::format("{:.6e} {:.6e}\n", fs[k], (k + 1.) / fs.size());
    if (!fs.empty())
      data += fmt::format("{:.6e} 1\n", fs.back());
    data += "EOD\n$fem << EOD\n";
    for (const auto *cases : {&result.training, &result.validation})
      for (const SafetyCase &c : *cases)
        if (c.solved())
          data += fmt::format("{:.6e}\n", c.safety_factor);
    data += "EOD\n";

    const double upper = fs.empty() ? 3. : fs[fs.size() * 99 / 100];
    const auto  &mc    = result.failure.monte_carlo;
    return data +
           fmt::format(
             "set multiplot layout 1,2\n"
             "set xrange [0:{0:.4f}]\n"
             "set xlabel 'floor safety factor FS (governing corner, "
             "verdict method)'\n"
             "set arrow from 1, graph 0 to 1, graph 1 nohead dt 2 lw 2 lc "
             "rgb 'red'\n"
             "set title 'FS over the uncertain inputs (surrogate, {1} "
             "draws)'\n"
             "set ylabel 'draws per bin'\n"
             "set style fill solid 0.5\n"
             "plot $fs using 1 bins=40 with boxes lc rgb '#4477aa' title "
             "'surrogate', $fem using 1:(0) with points pt 2 lc rgb 'black' "
             "title 'FEM cases'\n"
             "set title sprintf('P(FS < 1) = %.3f +- %.3f (95 %%)', {2:.6f}, "
             "{3:.6f})\n"
             "set ylabel 'P(FS <= x)'\n"
             "set yrange [0:1]\n"
             "set key bottom right\n"
             "plot $cdf using 1:2 with lines lw 2 lc rgb '#4477aa' title "
             "'cumulative distribution', {2:.6f} with lines dt 3 lc rgb "
             "'red' title 'P(FS < 1)'\n"
             "unset multiplot\n",
             std::max(1.2, upper),
             fs.size(),
             mc.probability,
             mc.half_width);
  }

  std::string
  sobol_indices_plot(const AssessmentResult &result)
  {
    const auto &s    = result.sobol;
    std::string data = "$indices << EOD\n";
    for (std::size_t i = 0; i < result.inputs.size(); ++i)
      data += fmt::format("{} {} {:.6f} {:.6f} {:.6f} {:.6f} {:.6f} {:.6f}\n",
                          i,
                          quoted(result.inputs[i].path),
                          s.first_order[i],
                          s.first_order_interval.getLowerBound()[i],
                          s.first_order_interval.getUpperBound()[i],
                          s.total_order[i],
                          s.total_order_interval.getLowerBound()[i],
                          s.total_order_interval.getUpperBound()[i]);
    data += "EOD\n";
    return data +
           "set title \"Sobol' indices of FS (inputs' marginals taken "
           "independent), 95 % intervals\"\n"
           "set ylabel 'index'\n"
           "set yrange [-0.05:1.25]\n"
           "set xtics rotate by -20\n"
           "set style fill solid 0.6\n"
           "set boxwidth 0.35\n"
           "set key top center horizontal\n"
           "plot $indices using ($1-0.18):3:xtic(2) with boxes lc rgb "
           "'#4477aa' title 'first order', '' using ($1-0.18):3:4:5 with "
           "yerrorbars lc rgb 'black' pt 0 notitle, '' using ($1+0.18):6 "
           "with boxes lc rgb '#ee6677' title 'total', '' using "
           "($1+0.18):6:7:8 with yerrorbars lc rgb 'black' pt 0 notitle\n";
  }

  std::string
  safety_factor_inputs_plot(const AssessmentResult &result)
  {
    std::vector<std::size_t> order(result.inputs.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return result.sobol.total_order[a] > result.sobol.total_order[b];
    });
    const std::size_t n_panels = std::min<std::size_t>(2, order.size());
    std::string       script;
    for (std::size_t p = 0; p < n_panels; ++p)
      script += case_data(result, order[p]);
    script += fmt::format("set multiplot layout 1,{}\n", n_panels);
    script += "set ylabel 'FS (FEM)'\n"
              "set key top left\n";
    for (std::size_t p = 0; p < n_panels; ++p)
      {
        const std::size_t i = order[p];
        script += fmt::format(
          "set xlabel {0}\n"
          "set title sprintf('total Sobol index %.2f', {1:.6f})\n"
          "plot $training_{2} using 1:2 with points pt 7 ps 0.6 lc rgb "
          "'#4477aa' title 'training cases', $held_{2} using 1:2 with "
          "points pt 9 ps 0.8 lc rgb '#ee6677' title 'held-out cases', 1 "
          "with lines dt 2 lw 2 lc rgb 'red' title 'FS = 1'\n",
          quoted(input_column(result.inputs[i])),
          result.sobol.total_order[i],
          i);
      }
    return script + "unset multiplot\n";
  }

  std::string
  design_limit_plot(const AssessmentResult &result)
  {
    const DesignLimit &d    = result.design_limit.value();
    std::string        data = "$curve << EOD\n";
    for (std::size_t k = 0; k < d.values.size(); ++k)
      data += fmt::format("{:.9e} {:.6e} {:.6e}\n",
                          d.values[k],
                          d.probabilities[k].probability,
                          d.probabilities[k].half_width);
    data += "EOD\n";
    std::string marks;
    for (const auto &[target, value] : d.limits)
      {
        marks += fmt::format("set arrow from graph 0, first {0} to graph 1, "
                             "first {0} nohead dt 3 lc rgb 'gray'\n",
                             target);
        if (value)
          marks += fmt::format(
            "set label {} at {:.9e}, {} point pt 7 lc rgb 'red' offset "
            "1,-1\n",
            quoted(fmt::format("P_f = {:g} at {:.4g}", target, *value)),
            *value,
            target);
      }
    return data + marks +
           fmt::format(
             "set title 'Design limit: P(FS < 1) with {0} fixed "
             "(surrogate)'\n"
             "set xlabel {1}\n"
             "set ylabel 'P(FS < 1)'\n"
             "set yrange [0:1]\n"
             "set key top left\n"
             "plot $curve using 1:($2-$3):($2+$3) with filledcurves lc rgb "
             "'#bbccee' title '95 % interval', $curve using 1:2 with "
             "linespoints pt 7 ps 0.6 lw 2 lc rgb '#4477aa' title "
             "'P(FS < 1)'\n",
             result.inputs[d.input].path,
             quoted(input_column(result.inputs[d.input])));
  }
} // namespace FloorBlock::Assessment
