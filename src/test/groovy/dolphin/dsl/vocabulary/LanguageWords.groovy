package dolphin.dsl.vocabulary

import dolphin.core.NodeSet
import dolphin.core.Platform
import dolphin.dsl.Engine
import dolphin.platform.MAVLinkLanguage

/** The vocabulary scripts get: the engine's words with the MAVLink language, as dolphin check and dolphin words read it. */
final class LanguageWords {

    private LanguageWords() {
    }

    static Vocabulary vocabulary() {
        Platform noVehicles = [getName: { 'no vehicles' }, getConnectedNodes: { new NodeSet() }] as Platform
        Engine engine = new Engine(noVehicles)
        engine.addExtension(new MAVLinkLanguage())
        engine.vocabulary()
    }
}
