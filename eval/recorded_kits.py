"""Recorded drum kits for the music corpus (eval/music_corpus.py): Hydrogen's kits from Debian's
hydrogen-drumkits, acoustic kits sampled at several strengths and electronic kits, read from each
kit's drumkit.xml. Each instrument is its velocity layers, (highest velocity, sample path), softest
first (which layer a hit plays: music_corpus.layer_for). Two parts, no kit (nor a kit sampled
from the same drums) in both."""
import pathlib
import xml.etree.ElementTree as ET

DRUMKITS = pathlib.Path("/usr/share/hydrogen/data/drumkits")
# part: kit directory: (kick, snare, hat) instrument names in its drumkit.xml.
KITS = {
    "recorded-tuning": {
        "BJA_Pacific": ("BassDrum", "Snare", "Hi Hat Closed"),
        "Millo_MultiLayered2": ("Kick", "Snare Rock", "Closed HH"),
        "Millo_MultiLayered3": ("Kick", "Snare Rock", "Closed HH"),
        "HardElectro1": ("Kick 1", "Snare", "Closed HH 1"),
        "VariBreaks": ("VariBreaks Kick 1", "VariBreaks Snare 1", "VariBreaks Hat 1 Cl"),
        "Audiophob": ("Kick", "Snare Rock", "Closed HH"),
    },
    "recorded-held-out": {
        "ForzeeStereo": ('Kick (Tama Superstar 22")', "Snare (Pearl Free Floating Maple 14x3.5)",
                         'Hi-Hat Closed (Paiste Alpha Metal edge 14")'),
        "The Black Pearl 1.0": ("Pearl Kick", "Pearl Snare", "Sabian Hat Closed"),
        "ColomboAcousticDrumkit": ("BassDrum", "Snare1", "Closed HH"),
        "ElectricEmpireKit": ("Kick Power", "Snare 1", "Hat Closed Bs"),
        "rumpf_kit_z01_h2": ("c3 - bass drum 1", "d3 - snare 1", "f#3 - hi-hat closed"),
    },
}
INSTRUMENTS = ("kick", "snare", "hat")


def layers(kit_dir, instrument_name):
    """[(highest velocity, sample path)] of one instrument, softest first."""
    root = ET.parse(kit_dir / "drumkit.xml").getroot()
    ns = root.tag[:root.tag.index("}") + 1] if root.tag.startswith("{") else ""
    for instrument in root.iter(ns + "instrument"):
        if instrument.findtext(ns + "name") != instrument_name:
            continue
        found = [(float(layer.findtext(ns + "max", "1")), kit_dir / layer.findtext(ns + "filename"))
                 for layer in instrument.iter(ns + "layer")]
        if not found:  # the older format: one sample, no layers
            found = [(1.0, kit_dir / instrument.findtext(ns + "filename"))]
        return sorted(found)
    raise KeyError(f"{kit_dir / 'drumkit.xml'}: no instrument {instrument_name!r}")


def kits(part):
    """{kit: {instrument: [(highest velocity, path)]}} of one part."""
    return {kit.replace(" 1.0", "").replace(" ", "-"):
            {role: layers(DRUMKITS / kit, name) for role, name in zip(INSTRUMENTS, names)}
            for kit, names in KITS[part].items()}

