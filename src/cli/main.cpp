// graspsim's command line: thin. Parse, call the library, map errors to exit codes:
// 0 success, 2 bad input (one line on stderr), 3 numerical failure, 4 a validation bound failed,
// 1 anything unexpected.

#include "command_line.h"
#include "output_folder.h"

#include "graspsim/error.h"

#include <iostream>

int main(int argc, char** argv) {
    graspsim::cli::removeFoldersOnInterrupt();
    graspsim::cli::CommandLine commandLine;
    try {
        commandLine.parse(argc, argv);
        return commandLine.run();
    } catch (const CLI::ParseError& e) {
        return commandLine.exit(e);
    } catch (const graspsim::InputError& e) {
        std::cerr << "graspsim: " << e.what() << "\n";
        return 2;
    } catch (const graspsim::NumericalError& e) {
        std::cerr << "graspsim: " << e.what() << "\n";
        return 3;
    } catch (const std::exception& e) {
        std::cerr << "graspsim: internal error: " << e.what() << "\n";
        return 1;
    }
}
