"""Copies pymavlink's MAVLink 2 definitions into OUT and adds the plan-id extension fields of common.xml
that MAVLink itself defines but pymavlink's copy (ArduPilot's) lacks: MISSION_COUNT.opaque_id,
MISSION_ACK.opaque_id, MISSION_CURRENT.mission_id, fence_id and rally_points_id. PX4 sends them: the id of
the plan on the vehicle, which is how the runtime tells the mission it uploaded from an earlier one.

Extension fields follow the message's others on the wire and are outside its CRC_EXTRA, so the messages
stay compatible with every peer; a field pymavlink already has is left as it is.

usage: mavlink_id_fields.py PYMAVLINK_DIALECTS_DIR OUT_DIR
"""
import pathlib
import shutil
import sys
import xml.etree.ElementTree as ET

ADDED = {
    "MISSION_COUNT": [("opaque_id", "Id of current on-vehicle mission, fence, or rally point plan (on vehicle)."
                                    " 0: the vehicle does not support ids.")],
    "MISSION_ACK": [("opaque_id", "Id of new on-vehicle mission, fence, or rally point plan (on upload to"
                                  " vehicle). 0: the vehicle does not support ids.")],
    "MISSION_CURRENT": [
        ("mission_id", "Id of current on-vehicle mission plan, or 0 if IDs are not supported or there is no"
                       " mission loaded."),
        ("fence_id", "Id of current on-vehicle fence plan, or 0 if IDs are not supported or there is no"
                     " fence loaded."),
        ("rally_points_id", "Id of current on-vehicle rally point plan, or 0 if IDs are not supported or there"
                            " are no rally points loaded."),
    ],
}


def main(src, out):
    src, out = pathlib.Path(src), pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    for xml in src.glob("*.xml"):
        shutil.copy(xml, out / xml.name)
    common = out / "common.xml"
    tree = ET.parse(common)
    messages = {m.get("name"): m for m in tree.getroot().iter("message")}
    for name, fields in ADDED.items():
        message = messages.get(name)
        if message is None or message.find("extensions") is None:
            sys.exit(f"mavlink_id_fields.py: {common} has no message {name} with extensions")
        have = {f.get("name") for f in message.iter("field")}
        for field, text in fields:
            if field not in have:
                element = ET.SubElement(message, "field", {"type": "uint32_t", "name": field, "invalid": "0"})
                element.text = text
    tree.write(common, encoding="utf-8", xml_declaration=True)


if __name__ == "__main__":
    main(*sys.argv[1:])
