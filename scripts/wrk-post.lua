-- wrk: POST the scene file named by $SCENE to every request.
local f = assert(io.open(os.getenv("SCENE"), "rb"))
wrk.method = "POST"
wrk.body = f:read("*a")
wrk.headers["Content-Type"] = "application/json"
f:close()
