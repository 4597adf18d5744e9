#include "body.h"

#include <algorithm>
#include <cstdint>
#include <string_view>
#include <vector>

#include "admission.h"
#include "raster/raster.h"
#include "request.h"
#include "request_id.h"

namespace rasterd {
namespace {

// The checks and counters of one body as it streams in, shared by the plain and multipart readers.
struct Reading {
  const ServiceConfig& config;
  Metrics& metrics;
  httplib::Response& res;
  RequestBudget& budget;
  std::int64_t memory_capacity;  ///< bytes, the whole memory budget
  Clock::time_point deadline;    ///< the whole body must have arrived by then
  bool over = false;             ///< more than config.max_body_bytes arrived
  bool late = false;             ///< bytes still arrived past `deadline`
  bool no_memory = false;        ///< the budget refused the next MiB
  Clock::time_point last_arrival = Clock::now();

  // Appends `n` bytes to `into`; false stops the reading (over the cap, late, or no memory for them).
  bool take(std::string& into, const char* data, std::size_t n) {
    last_arrival = Clock::now();
    t_request.bytes_in += n;
    over = t_request.bytes_in > config.max_body_bytes;
    late = !over && Clock::now() > deadline;
    if (over || late) return false;  // stop reading
    if (static_cast<std::int64_t>(t_request.bytes_in) > budget.held() && !budget.reserve(1 << 20))
      return !(no_memory = true);
    into.append(data, n);
    return true;
  }

  bool too_large() {
    return refuse(metrics, res,
                  problem(413, "body-too-large", "The request body is too large",
                          "the limit is " + std::to_string(config.max_body_bytes) + " bytes"),
                  "body_size");
  }
  bool no_memory_for(std::int64_t bytes) {
    return refuse_memory(metrics, res, bytes, memory_capacity, config.max_queue_wait, "memory");
  }
};

// Before any byte is read: the encoding, the declared length against the cap and the budget, and the
// declared length's reservation (the body's memory is reserved before it is read: declared, at once; else
// as it arrives, a MiB at a time). False with the refusal written.
bool accept_headers(Reading& r, const httplib::Request& req) {
  if (req.has_header("Content-Encoding") && req.get_header_value("Content-Encoding") != "identity")
    return refuse(r.metrics, r.res,
                  problem(415, "unsupported-encoding", "Compressed request bodies are not accepted",
                          "send the body uncompressed (got Content-Encoding: " +
                              req.get_header_value("Content-Encoding") + ")"),
                  "encoding");
  if (req.get_header_value<std::uint64_t>("Content-Length") > r.config.max_body_bytes) return r.too_large();
  // One larger than the whole budget could never be held.
  const auto declared = static_cast<std::int64_t>(req.get_header_value<std::uint64_t>("Content-Length"));
  if (declared > r.memory_capacity)
    return refuse(
        r.metrics, r.res,
        problem(413, "body-too-large", "The request body is too large",
                "the body's " + std::to_string(declared) + " bytes are more than the memory budget of " +
                    std::to_string(r.memory_capacity) + " bytes (--memory-budget)"),
        "body_size");
  if (!r.budget.reserve(declared)) return r.no_memory_for(declared);
  return true;
}

// The parts of a multipart body, into `into`. Sets `complete` as the ContentReader reports; false with a
// refusal written when the part names are not UTF-8, a name comes twice, or no part is the scene or model.
bool read_multipart(Reading& r, const httplib::ContentReader& reader, ReceivedBody& into, bool& complete) {
  std::string* current = nullptr;
  std::string bad_name;   // a part or file name that is not UTF-8: the names are echoed in errors
  std::string duplicate;  // two parts kept under one name: which bytes are meant is not knowable
  std::vector<PartName> parts;
  complete = reader(
      [&](const httplib::MultipartFormData& part) {
        for (const std::string* name : {&part.name, &part.filename})
          if (raster::first_invalid_utf8(*name) != std::string_view::npos) {
            bad_name = *name;
            return false;
          }
        if (part.name == "scene") {
          current = &into.body;
          return true;
        }
        if (part.name == "model") into.model_file_name = part.filename;
        const std::string key = upload_key(part.name, part.filename);
        parts.push_back({part.name, key});
        const auto [it, added] = into.uploads.try_emplace(key);
        if (!added) {
          duplicate = key;
          return false;
        }
        current = &it->second;
        return true;
      },
      [&](const char* data, std::size_t n) { return r.take(*current, data, n); });
  if (!bad_name.empty()) {
    try {
      raster::require_utf8(bad_name, "a multipart part or file name");
    } catch (const raster::SceneError& e) {
      return refuse(r.metrics, r.res, problem_from(e), "encoding");
    }
  }
  if (!duplicate.empty())
    return refuse(r.metrics, r.res,
                  problem(400, "duplicate-part", "Two multipart parts have the same name",
                          "more than one part is named \"" + duplicate +
                              "\" (texture parts are named by their file name); send each once"),
                  "duplicate_part");
  add_part_names(into.uploads, parts);
  if (const std::string unnamed =
          adopt_main_part(into.body, into.uploads, parts, &into.model_file_name, &into.sniffed);
      !unnamed.empty())
    return refuse(r.metrics, r.res,
                  problem(400, "missing-part", "No scene or model part in the upload", unnamed),
                  "missing_part");
  return true;
}

// After the reader stopped: why, if the body is not whole. False with the refusal written.
bool accept_ending(Reading& r, bool complete) {
  if (r.over) return r.too_large();
  if (r.no_memory) return r.no_memory_for(1 << 20);
  // A client that went quiet for the socket's read timeout also failed to deliver its body in time;
  // one whose connection ended is past answering anyway.
  if (!complete && Clock::now() - r.last_arrival >= read_timeout(r.config)) r.late = true;
  if (r.late)
    return refuse(r.metrics, r.res,
                  problem(408, "body-timeout", "The request body did not arrive in time",
                          "the whole body must arrive within " +
                              std::to_string(r.config.body_deadline.count()) + " ms"),
                  "body_timeout");
  if (!complete)  // the connection ended early, or the multipart framing is broken
    return refuse(r.metrics, r.res,
                  problem(400, "incomplete-body", "The request body is incomplete or malformed",
                          "the body ended before its declared length, or its multipart framing is broken"),
                  "body_incomplete");
  return true;
}

}  // namespace

std::chrono::milliseconds read_timeout(const ServiceConfig& config) {
  return std::min<std::chrono::milliseconds>(config.body_deadline, std::chrono::milliseconds(5000));
}

bool read_body(const ServiceConfig& config, Metrics& metrics, const httplib::Request& req,
               httplib::Response& res, const httplib::ContentReader& reader, RequestBudget& budget,
               std::int64_t memory_capacity, ReceivedBody& into) {
  Reading r{config, metrics, res, budget, memory_capacity, t_request.start + config.body_deadline};
  if (!accept_headers(r, req)) return false;
  r.last_arrival = Clock::now();  // the reservation may have waited: quiet time counts from here
  // RFC 9112 6.3: a request with neither Content-Length nor chunked framing has no body (`curl -X POST`);
  // reading on would wait for bytes that never come.
  const bool chunked = req.get_header_value("Transfer-Encoding").find("chunked") != std::string::npos;
  if (!req.has_header("Content-Length") && !chunked) return true;
  bool complete;
  if (req.is_multipart_form_data()) {
    if (!read_multipart(r, reader, into, complete)) return false;
  } else {
    if (const auto declared = req.get_header_value<std::uint64_t>("Content-Length"))
      into.body.reserve(declared);
    complete = reader([&](const char* data, std::size_t n) { return r.take(into.body, data, n); });
  }
  return accept_ending(r, complete);
}

}  // namespace rasterd
