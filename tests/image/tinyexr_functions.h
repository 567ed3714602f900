#pragma once
// tinyexr entry points for tests that write or inspect EXR files independently of the
// engine's own reader and writer (the image tests link tinyexr themselves).

#include <tinyexr.h>

#include <stdexcept>
#include <string>

namespace bounce::test {

struct TinyexrFunctions {
  decltype(&InitEXRHeader) initHeader;
  decltype(&InitEXRImage) initImage;
  decltype(&FreeEXRHeader) freeHeader;
  decltype(&FreeEXRImage) freeImage;
  decltype(&FreeEXRErrorMessage) freeErrorMessage;
  decltype(&ParseEXRVersionFromFile) parseVersionFromFile;
  decltype(&ParseEXRHeaderFromFile) parseHeaderFromFile;
  decltype(&LoadEXRImageFromFile) loadImageFromFile;
  decltype(&SaveEXRImageToFile) saveImageToFile;
};

inline const TinyexrFunctions& tinyexr() {
  static const TinyexrFunctions functions = {
      &InitEXRHeader,          &InitEXRImage,         &FreeEXRHeader,
      &FreeEXRImage,           &FreeEXRErrorMessage,  &ParseEXRVersionFromFile,
      &ParseEXRHeaderFromFile, &LoadEXRImageFromFile, &SaveEXRImageToFile,
  };
  return functions;
}

}  // namespace bounce::test
