// The `rasterd serve` flags. In: `--flag value` (or `--flag=value`) arguments, and RASTERD_<FLAG> (and
// PORT) in the environment. Out: the ServiceConfig, host and port they set over the defaults, or an error
// message; and the text of `rasterd serve --help`, one line per flag.
#pragma once

#include <string>

#include "service_config.h"

namespace rasterd {

/// Reads the configuration from `--flag value` arguments over environment variables over the values
/// `config`, `host` and `port` already hold. Returns an error message, empty on success.
std::string parse_service_flags(int argc, const char* const* argv, ServiceConfig& config, std::string& host,
                                int& port);

/// The text of `rasterd serve --help`.
std::string service_help();

}  // namespace rasterd
