package dolphin.dsl.vocabulary

import dolphin.core.VehiclelessPlatform
import dolphin.dsl.Engine
import dolphin.platform.MAVLinkLanguage

/** The vocabulary scripts get: the engine's words with the MAVLink language, as dolphin check and dolphin words read it. */
final class LanguageWords {

    private LanguageWords() {
    }

    static Vocabulary vocabulary() {
        Engine engine = new Engine(new VehiclelessPlatform('no vehicles'))
        engine.addExtension(new MAVLinkLanguage())
        engine.vocabulary()
    }
}
