// PNG output through VTK. vtkImageData keeps row 0 at the bottom, as Image does, and
// vtkPNGWriter writes the top row first, so rows are copied as they are.
#include <cmath>
#include <filesystem>
#include <string>

#include <unistd.h>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>

#include "harness/render/compositor.h"
#include "harness/scene/input_error.h"

namespace vob {

void write_png(const Image& img, const std::string& path) {
  if (img.width <= 0 || img.height <= 0 || img.rgb.size() != size_t(img.width) * img.height * 3)
    throw InputError(path, "image", "is empty or its pixel data does not match its size");
  // A missing directory is reported here, before VTK prints its own error.
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty() && !std::filesystem::is_directory(parent))
    throw InputError(path, "png", "directory " + parent.string() + " does not exist");
  vtkNew<vtkImageData> data;
  data->SetDimensions(img.width, img.height, 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(data->GetScalarPointer());
  for (size_t i = 0; i < img.rgb.size(); ++i) {
    const float v = std::isfinite(img.rgb[i]) ? std::clamp(img.rgb[i], 0.0f, 1.0f) : 0.0f;
    out[i] = static_cast<unsigned char>(std::lround(v * 255.0f));
  }
  // Written beside the target, then renamed: readers never see a partial file.
  const std::string tmp = path + ".tmp" + std::to_string(::getpid());
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(tmp.c_str());
  writer->SetInputData(data);
  writer->Write();
  std::error_code ec;
  if (writer->GetErrorCode() != 0 || !std::filesystem::exists(tmp, ec)) {
    std::filesystem::remove(tmp, ec);
    throw InputError(path, "png", "cannot be written");
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw InputError(path, "png", "cannot be renamed into place: " + ec.message());
  }
}

Image read_png(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path, "png", "does not exist");
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* data = reader->GetOutput();
  int dims[3] = {0, 0, 0};
  data->GetDimensions(dims);
  const int nc = data->GetNumberOfScalarComponents();
  if (dims[0] <= 0 || dims[1] <= 0 || nc < 3 || data->GetScalarType() != VTK_UNSIGNED_CHAR)
    throw InputError(path, "png", "is not an 8-bit RGB image");
  Image img;
  img.width = dims[0];
  img.height = dims[1];
  img.rgb.resize(size_t(img.width) * img.height * 3);
  const auto* in = static_cast<const unsigned char*>(data->GetScalarPointer());
  for (size_t p = 0; p < size_t(img.width) * img.height; ++p)
    for (int c = 0; c < 3; ++c) img.rgb[3 * p + c] = in[p * nc + c] / 255.0f;
  return img;
}

}  // namespace vob
