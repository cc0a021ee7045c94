// FloorBlock benchmark (issues #4 "Speed", #6 "Benchmarks"): times the
// default scene's mesh, assembly, linear solve, Newton iteration and whole
// contact solve on refined meshes, and the Hertz verification, through the
// project's own library code; prints Google Benchmark's table, then a
// markdown summary (tables, fitted exponents, cost ratios). Not a test.
#include <common/input_error.h>

#include <deal.II/base/mpi.h>

#include <benchmark/benchmark.h>

#include <filesystem>
#include <iostream>
#include <string>
#include <thread>

#include "benchmark_options.h"
#include "loaded_blas.h"
#include "measurements.h"
#include "scene_benchmarks.h"
#include "summary_report.h"

int
main(int argc, char **argv)
{
  using namespace FloorBlock::Benchmark;
  // One thread: the numbers are per core, and the machine is shared.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  RunContext                               context;
  context.blas        = inspect_and_limit_blas();
  context.load_before = load_average();
  context.n_cores     = std::thread::hardware_concurrency();

  BenchmarkOptions options;
  try
    {
      options = parse_options(
        argc, argv, std::string(FLOORBLOCK_SOURCE_DIR) + "/params/default.prm");
    }
  catch (const FloorBlock::InputError &error)
    {
      std::cerr << error.what() << "\n" << options_help();
      return FloorBlock::exit_code::bad_input;
    }
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--help")
      std::cout << options_help() << "\n";
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return FloorBlock::exit_code::bad_input;

  register_scene_benchmarks(options);
  register_hertz_benchmarks(options);
  try
    {
      benchmark::RunSpecifiedBenchmarks();
    }
  catch (const FloorBlock::InputError &error)
    {
      std::cerr << error.what() << "\n";
      return FloorBlock::exit_code::bad_input;
    }
  benchmark::Shutdown();
  std::filesystem::remove_all(options.work_directory);

  // Nothing ran (--benchmark_list_tests, or a filter that matched nothing).
  if (records().levels.empty() && records().hertz.empty())
    return FloorBlock::exit_code::success;
  context.load_after = load_average();
  std::cout << "\n" << summary_markdown(records(), context);
  return FloorBlock::exit_code::success;
}
