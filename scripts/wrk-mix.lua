-- wrk: a web page's mix, one request after another on each connection: small scenes (a thumbnail, an
-- example), a bad body (an error a page shows), and a model (the knot, by multipart). Counts answers by
-- status and prints them at the end as "status N COUNT".
local function read(path)
  local f = assert(io.open(path, "rb"))
  local s = f:read("*a")
  f:close()
  return s
end
local boundary = "rasterdmix"
local model = read("examples/models/knot.obj")
local requests = {
  {body = read("examples/gradient.json"), type = "application/json"},
  {body = read("examples/star.json"), type = "application/json"},
  {body = '{"width": 64, "height": 64, "primitives": [{"type": "triangle", "points": [[0,0],[64,0],[0,64]]}]}',
   type = "application/json"},
  {body = '{"width": 64, "height": "64"}', type = "application/json"},
  {body = "--" .. boundary .. '\r\nContent-Disposition: form-data; name="model"; filename="knot.obj"\r\n\r\n' ..
          model .. "\r\n--" .. boundary .. "--\r\n",
   type = "multipart/form-data; boundary=" .. boundary},
}
local threads = {}

function setup(thread)
  table.insert(threads, thread)
end

function init(args)
  counter = 0    -- globals: done() reads them from each thread's state
  statuses = {}
end

function request()
  counter = counter + 1
  local r = requests[(counter % #requests) + 1]
  return wrk.format("POST", "/render", {["Content-Type"] = r.type}, r.body)
end

function response(status)
  statuses[status] = (statuses[status] or 0) + 1
end

function done()
  local total = {}
  for _, t in ipairs(threads) do
    local s = t:get("statuses")
    for k, v in pairs(s) do total[k] = (total[k] or 0) + v end
  end
  for k, v in pairs(total) do io.write(string.format("status %d %d\n", k, v)) end
end
