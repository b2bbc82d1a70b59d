// The fuzz targets of `rgctl fuzz` (issue 25): each hands arbitrary bytes to one real parser of
// core/ as the file or text it reads. Expected rejections (rgnav::Error and its subclasses) are
// caught; anything else - another exception, a crash, a sanitizer report, a hang, a huge
// allocation - escapes and is a finding. The same functions run under libFuzzer (FuzzerMain.cpp,
// build-fuzz/) and, on the saved inputs of earlier findings, in the regression test.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace rgnav::fuzz {

using FuzzTarget = void (*)(const std::uint8_t* data, std::size_t size);

struct NamedFuzzTarget {
  std::string_view name;  // also the folder of its corpus, crashes and regression inputs
  FuzzTarget run;
};

// Every target, in the order `rgctl fuzz` runs them.
const std::vector<NamedFuzzTarget>& fuzzTargets();
// Throws InvalidArgumentError for a name that is not a target.
FuzzTarget fuzzTarget(std::string_view name);

void fuzzCarmenReader(const std::uint8_t* data, std::size_t size);
void fuzzIntelJsonReader(const std::uint8_t* data, std::size_t size);
void fuzzSetConfig(const std::uint8_t* data, std::size_t size);
void fuzzVectorWorld(const std::uint8_t* data, std::size_t size);
void fuzzSimulationConfig(const std::uint8_t* data, std::size_t size);
void fuzzModuleConfig(const std::uint8_t* data, std::size_t size);
void fuzzSlamCheckpoint(const std::uint8_t* data, std::size_t size);
void fuzzDetectionCheckpoint(const std::uint8_t* data, std::size_t size);
void fuzzRgMapCheckpoint(const std::uint8_t* data, std::size_t size);
void fuzzRgMapJson(const std::uint8_t* data, std::size_t size);
void fuzzHmmModelFile(const std::uint8_t* data, std::size_t size);

}  // namespace rgnav::fuzz
