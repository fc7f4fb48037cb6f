"""The dance settings, defined once: the operators' parameters and the scene's settings that
the panel shows and passes to them (tooltips and defaults included)."""

from bpy.props import BoolProperty, FloatProperty, IntProperty, StringProperty

SONG = StringProperty(name="Song", subtype="FILE_PATH",
                      description="The song (WAV, MP3, Ogg, FLAC): it drives the dance and is "
                                  "added as a sound strip at the scene's start")
FPS = IntProperty(name="FPS", default=30, min=1, max=240,
                  description="Frames per second: the scene's frame rate is set to it")
START = FloatProperty(name="Start", default=0.0, min=0.0, unit="TIME_ABSOLUTE",
                      description="Where the dance starts in the song, seconds")
DURATION = FloatProperty(name="Duration", default=0.0, min=0.0, unit="TIME_ABSOLUTE",
                         description="Seconds of song to dance (0: to the song's end)")
MAPPING = StringProperty(name="Mapping", subtype="FILE_PATH",
                         description="A mapping file (JSON), e.g. saved from the gallery; "
                                     "empty: the gallery item")
ITEM = IntProperty(name="Gallery item", default=0, min=0, max=8,
                   description="Initial-gallery item 1–8 as the gallery numbers them (0: the "
                               "item that moves this mesh most on the song)")
K = IntProperty(name="Harmonics (k)", default=150, min=4, max=2000,
                description="Harmonics solved: more allow finer motion and take longer")
RIG_FILE = StringProperty(name="Rig file", subtype="FILE_PATH",
                          description="The glTF (.glb) the armature was imported from "
                                      "(remembered on the armature)")
MODES = StringProperty(name="Modes", default="",
                       description="Vibration modes that move, e.g. 0,2,5-8 (empty: the rig's "
                                   "default palette)")
AMPLITUDE = FloatProperty(name="Amplitude", default=0.0, min=0.0, max=3.14159,
                          description="Largest body rotation of each mode at full drive, "
                                      "radians (0: the default)")
TIME_SCALE = FloatProperty(name="Time scale", default=0.0, min=0.0, max=1000.0,
                           description="Multiply the natural frequencies (0: the default)")
ON_BEAT = BoolProperty(name="On the beat", default=True,
                       description="The sway turns on the song's beats (off: the modes run free "
                                   "at their own frequencies, as in the thesis)")
OPTIONS = StringProperty(name="More options", default="",
                         description="More options of `eigendance animate-rig`, as typed on "
                                     "its command line (e.g. --offset 1)")
