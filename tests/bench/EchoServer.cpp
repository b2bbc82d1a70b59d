// rgnav-bench-echo: the bare omniORB baseline of the middleware benchmark: returns byte
// sequences of a requested size, with no conversion, buffer or lock behind it.
#include "Echo.hh"
#include "servers/common/ServerRuntime.h"

namespace {

class EchoImpl : public POA_RGNavBench::Echo {
 public:
  RGNavBench::Bytes* fetch(CORBA::ULong size) override {
    auto* bytes = new RGNavBench::Bytes(size);
    bytes->length(size);
    return bytes;
  }
  RGNavBench::Bytes* roundTrip(const RGNavBench::Bytes& data) override { return new RGNavBench::Bytes(data); }
};

}  // namespace

int main(int argc, char** argv) {
  return rgnav::runServer(argc, argv, {}, [](rgnav::ServerRuntime& runtime) { runtime.activate("Echo", new EchoImpl); });
}
