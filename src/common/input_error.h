#pragma once

#include <stdexcept>
#include <string>

namespace FloorBlock
{
  /**
   * @brief Bad user input: an unknown or out-of-range parameter, an unreadable
   * file, or a scene whose geometry or physics has no answer.
   *
   * The command line turns it into one message and exit code 2
   * (FloorBlock::exit_code::bad_input), before anything is written.
   */
  class InputError : public std::runtime_error
  {
  public:
    explicit InputError(const std::string &message);

    /**
     * @brief The usual form: "parameter '<name>' = '<value>': <allowed>".
     * @param[in] parameter Full path, e.g. "Joints/Bedding friction angle".
     * @param[in] value The offending value as the user wrote it.
     * @param[in] allowed What would be accepted, with units.
     */
    InputError(const std::string &parameter,
               const std::string &value,
               const std::string &allowed);
  };

  /** Process exit codes shared by every subcommand. */
  namespace exit_code
  {
    constexpr int success     = 0;
    constexpr int failure     = 1; ///< numerical failure or failed check
    constexpr int bad_input   = 2;
    constexpr int interrupted = 130; ///< 128 + SIGINT, the shell convention
  }                                  // namespace exit_code
} // namespace FloorBlock
