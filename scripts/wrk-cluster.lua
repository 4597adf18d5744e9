-- wrk for scripts/test-cluster: POSTs the scene file named by $SCENE, counts the answers by status and the
-- 503s that came without Retry-After, and prints them at the end as "status N COUNT" / "no_retry_after N".
local f = assert(io.open(os.getenv("SCENE"), "rb"))
wrk.method = "POST"
wrk.body = f:read("*a")
wrk.headers["Content-Type"] = "application/json"
f:close()

local threads = {}
function setup(thread) table.insert(threads, thread) end

function init(args)
  counts = {}
  no_retry_after = 0
end

function response(status, headers, body)
  counts[status] = (counts[status] or 0) + 1
  if status == 503 and not (headers["Retry-After"] or headers["retry-after"]) then
    no_retry_after = no_retry_after + 1
  end
end

function done(summary, latency, requests)
  local total, missing = {}, 0
  for _, t in ipairs(threads) do
    for status, n in pairs(t:get("counts")) do total[status] = (total[status] or 0) + n end
    missing = missing + t:get("no_retry_after")
  end
  for status, n in pairs(total) do io.write(string.format("status %d %d\n", status, n)) end
  io.write(string.format("no_retry_after %d\n", missing))
  local e = summary.errors
  io.write(string.format("socket_errors %d %d %d %d\n", e.connect, e.read, e.write, e.timeout))
end
