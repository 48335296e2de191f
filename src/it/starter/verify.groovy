// The README's starter, built against the just-built library: its one scene test ran, passed and
// wrote the PNG it promises (500x500).
def log = new File(basedir, 'build.log').text
assert log.contains('Tests run: 1, Failures: 0, Errors: 0, Skipped: 0') : 'the scene test did not run and pass'
def png = new File(basedir, 'images/twoSpheres.png')
assert png.isFile() : "no image at ${png}"
def image = javax.imageio.ImageIO.read(png)
assert image.width == 500 && image.height == 500 : "image is ${image.width}x${image.height}, not 500x500"
true
