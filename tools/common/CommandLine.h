// parseCommandLine: the command-line front end every RG Nav program shares: options (and
// positional arguments) parsed with Boost.Program_options, --help printed to stdout.
#pragma once

#include <boost/program_options.hpp>
#include <iostream>

namespace rgnav {

// Fills the variables bound in `options`. Returns false if --help was given (the help is
// printed; the program should exit 0). Throws boost::program_options::error on bad input.
inline bool parseCommandLine(int argc, char** argv, const boost::program_options::options_description& options,
                             const boost::program_options::positional_options_description& positional = {}) {
  namespace po = boost::program_options;
  po::variables_map vm;
  po::store(po::command_line_parser(argc, argv).options(options).positional(positional).run(), vm);
  if (vm.count("help")) {
    std::cout << options << std::endl;
    return false;
  }
  po::notify(vm);
  return true;
}

}  // namespace rgnav
