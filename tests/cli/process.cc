#include "process.h"

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace FloorBlockTest
{
  std::string
  read_text(const std::string &path)
  {
    std::ifstream      in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  namespace
  {
    /** Splits one CSV line; fields in double quotes may hold commas. */
    std::vector<std::string>
    split_csv(const std::string &line)
    {
      std::vector<std::string> fields(1);
      bool                     quoted = false;
      for (const char character : line)
        if (character == '"')
          quoted = !quoted;
        else if (character == ',' && !quoted)
          fields.emplace_back();
        else
          fields.back() += character;
      return fields;
    }
  } // namespace

  CsvTable
  read_csv(const std::string &path)
  {
    std::ifstream in(path);
    CsvTable      table;
    for (std::string line; std::getline(in, line);)
      {
        if (line.empty() || line[0] == '#')
          continue;
        const auto fields = split_csv(line);
        if (table.columns.empty())
          {
            table.columns = fields;
            continue;
          }
        CsvRow row;
        for (std::size_t k = 0; k < fields.size() && k < table.columns.size();
             ++k)
          row[table.columns[k]] = fields[k];
        table.rows.push_back(row);
      }
    return table;
  }

  double
  number_in(const CsvRow &row, const std::string &column)
  {
    return std::stod(row.at(column));
  }

  nlohmann::json
  read_json(const std::string &path)
  {
    return nlohmann::json::parse(read_text(path));
  }

  bool
  has_non_finite_value(const std::string &text)
  {
    static const std::regex non_finite(
      "(^|[^A-Za-z])[-+]?(nan|inf)([^A-Za-z]|$)", std::regex::icase);
    return std::regex_search(text, non_finite);
  }

  namespace
  {
    /** Runs a shell @p command; its exit code and its output. */
    ProcessResult
    run_shell(const std::string &command)
    {
      FILE                  *pipe = ::popen(command.c_str(), "r");
      std::string            output;
      std::array<char, 4096> buffer;
      while (const std::size_t n =
               std::fread(buffer.data(), 1, buffer.size(), pipe))
        output.append(buffer.data(), n);
      const int status = ::pclose(pipe);
      return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
    }
  } // namespace

  ProcessResult
  run_floorblock(const std::string &arguments)
  {
    return run_shell(std::string("cd ") + FLOORBLOCK_SOURCE_DIR + " && " +
                     FLOORBLOCK_EXECUTABLE + " " + arguments + " 2>&1");
  }

#ifdef FLOORBLOCK_MPIEXEC
  ProcessResult
  run_floorblock_on_processes(const unsigned int n_processes,
                              const std::string &arguments,
                              const unsigned int time_limit_seconds)
  {
    // CI runs as root, which Open MPI refuses unless told; a machine with
    // fewer cores than processes needs oversubscription.
    const std::string time_limit =
      time_limit_seconds > 0 ?
        "timeout " + std::to_string(time_limit_seconds) + " " :
        std::string();
    return run_shell(
      std::string("cd ") + FLOORBLOCK_SOURCE_DIR +
      " && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 " +
      time_limit + FLOORBLOCK_MPIEXEC + " " + FLOORBLOCK_MPIEXEC_NUMPROC_FLAG +
      " " + std::to_string(n_processes) + " --oversubscribe " +
      FLOORBLOCK_EXECUTABLE + " " + arguments + " 2>&1");
  }
#endif

  int
  start_floorblock(const std::string &arguments, const std::string &log_path)
  {
    const std::string command = std::string("cd ") + FLOORBLOCK_SOURCE_DIR +
                                " && exec " + FLOORBLOCK_EXECUTABLE + " " +
                                arguments + " > " + shell_quoted(log_path) +
                                " 2>&1";
    const pid_t child = ::fork();
    if (child == 0)
      {
        ::execl("/bin/sh", "sh", "-c", command.c_str(), nullptr);
        ::_exit(127);
      }
    return child;
  }

  int
  wait_for_exit(const int process_id)
  {
    int status = 0;
    ::waitpid(process_id, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  std::string
  fresh_output_folder(const std::string &name)
  {
    const auto folder =
      std::filesystem::temp_directory_path() /
      ("floorblock_cli_" + std::to_string(::getpid()) + "_" + name);
    std::filesystem::remove_all(folder);
    return folder.string();
  }

  std::string
  shell_quoted(const std::string &text)
  {
    std::string result = "'";
    for (const char c : text)
      result += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return result + "'";
  }
} // namespace FloorBlockTest
