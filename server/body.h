// Reading a POST body. In: the request's headers and its ContentReader, the service's body cap and
// deadline, and the request's memory budget. Out: the scene or model bytes, the multipart uploads, the
// model part's file name and, when a part was adopted, the request's sniff; or false with a problem written
// (415, 413, 408, 400 or 503) and counted.
#pragma once

#include <chrono>
#include <optional>
#include <string>

#include <httplib.h>

#include "memory_budget.h"
#include "metrics.h"
#include "raster/scene.h"
#include "request.h"
#include "service_config.h"

namespace rasterd {

/// What a POST sent.
struct ReceivedBody {
  std::string body;                ///< the scene or model (a multipart upload's "scene" or main part)
  raster::Uploads uploads;         ///< multipart parts other than the scene, by upload key
  std::string model_file_name;     ///< of the multipart part that carried the model; empty if none
  std::optional<Sniffed> sniffed;  ///< the request's sniff, made when a part was adopted (adopt_main_part)
};

/// How long a connection may stay silent: the body deadline, at most 5 s (also between requests' headers).
std::chrono::milliseconds read_timeout(const ServiceConfig& config);

// Refuses compressed bodies and bodies declared over the cap before reading anything; then reads the
// body through the ContentReader. cpp-httplib 0.11 caps a buffered form-urlencoded body (what
// `curl -d` sends) at 8 KiB with a 413, but a ContentReader route receives any body. The cap is counted
// while streaming (chunked bodies declare no length) and the deadline holds whatever the pace of the
// bytes. Multipart parts go to `uploads`, except "scene", which becomes the body (and, without a "scene"
// or "model" part, the part adopt_main_part chooses, which becomes the body or the model).
bool read_body(const ServiceConfig& config, Metrics& metrics, const httplib::Request& req,
               httplib::Response& res, const httplib::ContentReader& reader, RequestBudget& budget,
               std::int64_t memory_capacity, ReceivedBody& into);

}  // namespace rasterd
