// readGrayImage: format dispatch by magic number.
#include "core/sim/world/ImageFile.h"

#include "core/common/Errors.h"
#include "core/sim/world/FileBytes.h"
#include "core/sim/world/PgmIo.h"
#include "core/sim/world/PngIo.h"

namespace rgnav {

GrayImage readGrayImage(const std::string& path) {
  const std::string bytes = readFileBytes(path);
  if (isPng(bytes)) return decodePngGray(bytes, path);
  if (isPgm(bytes)) return decodePgm(bytes, path);
  throw FormatError(path, 0, "neither a PNG nor a PGM (P5/P2) image");
}

}  // namespace rgnav
