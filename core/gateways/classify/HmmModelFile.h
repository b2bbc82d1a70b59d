// Model files of the HMM gateway classifier: every trained HMM with its class and class prior in
// a versioned plain text format that the GatewayDetection server loads from config/.
//
// Format version 1: one record per line, fields separated by blanks; blank lines and lines
// whose first field starts with '#' are ignored. Records, in this order:
//   rgnav-gateway-hmms 1
//   dimension <d>                          observation dimension, shared by all models
//   models <n>
//   n times:
//     model <class name> <class prior> <Q> class name as gatewayClassName, e.g. T-Junction
//     prior <pi_1 .. pi_Q>
//     transitions <A(i,1) .. A(i,Q)>       Q records, row i of A
//     Q times:
//       state <M>
//       M times:
//         component <mixture weight>
//         mean <mu_1 .. mu_d>
//         covariance <U(r,1) .. U(r,d)>    d records, row r of the full covariance
//   end
// Numbers are written in the shortest form that reads back to the same double, so a round trip
// is exact. Anything else - a wrong magic or version, a missing, misplaced or extra record, a
// bad number, an invalid model (probabilities that do not sum to 1, a covariance that is not
// positive definite, a class given twice) or content after `end` - is a FormatError naming the
// file and line; an unreadable file is a FileError.
#pragma once

#include <string>

#include "core/gateways/classify/HmmClassifier.h"

namespace rgnav {

// Writes atomically (write + rename); throws FileError.
void saveHmmModels(const std::string& path, const HmmClassifier& classifier);

HmmClassifier loadHmmModels(const std::string& path);

}  // namespace rgnav
