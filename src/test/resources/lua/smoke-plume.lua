-- smoke-plume.lua: a simulated smoke sensor. Twice a second it sends NAMED_VALUE_FLOAT "SMOKE" with
-- the reading of a made-up plume at the vehicle's own position: PEAK * (1 - d / RADIUS) within RADIUS
-- metres of the plume's centre, 0 outside (d: horizontal distance from the vehicle to the centre).
-- Nothing is sent while the vehicle has no position estimate.
--
-- Install: set SCR_ENABLE 1 and reboot; put this file in the SD card's APM/scripts/ folder and reboot
-- again. In SITL: a scripts/ folder in the directory SITL runs in, and SCR_ENABLE 1 in --defaults.
--
-- The plume is the constants below, or, where non-zero, SCR_USER1 centre latitude (degrees),
-- SCR_USER2 centre longitude (degrees), SCR_USER3 radius (m), SCR_USER4 peak value. Parameters are
-- float32: a latitude of about 40 degrees is held to about 4e-6 degrees (0.4 m).

local CENTRE_LAT = 40.4461    -- degrees, about 210 m north of the test home 40.444233, -7.375234
local CENTRE_LON = -7.3752    -- degrees
local RADIUS_M = 60
local PEAK = 100
local PERIOD_MS = 500         -- 2 Hz

local function setting(name, default)
  local value = param:get(name)
  if value == nil or value == 0 then
    return default
  end
  return value
end

local function update()
  local here = ahrs:get_location()
  if here then
    local centre = Location()
    centre:lat(math.floor(setting('SCR_USER1', CENTRE_LAT) * 1e7 + 0.5))
    centre:lng(math.floor(setting('SCR_USER2', CENTRE_LON) * 1e7 + 0.5))
    local radius = setting('SCR_USER3', RADIUS_M)
    local d = here:get_distance(centre)
    local value = 0
    if d < radius then
      value = setting('SCR_USER4', PEAK) * (1 - d / radius)
    end
    gcs:send_named_float('SMOKE', value)
  end
  return update, PERIOD_MS
end

return update()
