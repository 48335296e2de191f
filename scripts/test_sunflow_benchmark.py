"""scripts/sunflow_benchmark.py without Sunflow or a JVM: command templates, the statistics read from
each side's output, the arguments refused, and that the Sunflow scene holds the port's primitives."""
from __future__ import annotations

import random
import re
from pathlib import Path

import pytest

import sunflow_benchmark as sb


def test_a_template_keeps_its_environment_and_takes_the_arguments_where_asked():
    env, words = sb.split_template("RAYTRACER_JAVA_OPTS='-XX:TieredStopAtLevel=4 -Xmx1g' A=1 ./raytracer {args} --seed=3")
    assert env == {"RAYTRACER_JAVA_OPTS": "-XX:TieredStopAtLevel=4 -Xmx1g", "A": "1"}
    assert sb.fill(words, ["s.xml", "--aa=NONE"]) == ["./raytracer", "s.xml", "--aa=NONE", "--seed=3"]


def test_without_args_the_arguments_go_at_the_end():
    env, words = sb.split_template("java -XX:+UseSerialGC -jar target/raytracer.jar")
    assert env == {}
    assert sb.fill(words, ["s.xml"]) == ["java", "-XX:+UseSerialGC", "-jar", "target/raytracer.jar", "s.xml"]


def test_a_template_of_variables_only_is_refused():
    with pytest.raises(ValueError):
        sb.split_template("A=1 B=2")


def test_each_case_asks_both_sides_for_the_same_sampling():
    cmd = sb.sunflow_command(Path("/x/sunflow.jar"), Path("/x/s.sc"), 2, ["-Xmx1g"])
    assert cmd.argv("16spp", Path("o.png"), True)[1:] == [
        "-Xmx1g", "-jar", "/x/sunflow.jar", "-nogui", "-o", "o.png", "-threads", "2", "-aa", "2", "2", "/x/s.sc"]
    ours = sb.our_command("j", "java -jar target/raytracer.jar", Path("/x/s.xml"), 2)
    assert ours.argv("adaptive", Path("o.png"), True) == [
        "java", "-jar", "target/raytracer.jar", "/x/s.xml", "--threads=2", "--aa=ADAPTIVE", "--output=o.png", "--quiet"]
    assert "--quiet" not in ours.argv("1spp", Path("o.png"), False)


def test_rays_per_pixel_from_either_sides_statistics():
    sunflow = ("SCENE  info  :       eye              662808      1.84         1.00       13.82%\n"
               "SCENE  info  :       shadow          3000000      8.33         4.53       62.55%\n"
               "SCENE  info  :       total           4795920     13.32         7.24      100.00%\n")
    assert sb.rays_per_pixel(sunflow, False, 360000) == pytest.approx((662808 / 360000, 4795920 / 360000))
    ours = "render x: 1.082 s, 600x600 [NONE] of scene 's', 360000 px, rays: camera 360000, shadow 1744211, secondary 400643, 1.00"
    assert sb.rays_per_pixel(ours, True, 360000) == pytest.approx((1.0, 2504854 / 360000))
    assert sb.rays_per_pixel("nothing", True, 1) is None and sb.rays_per_pixel("nothing", False, 1) is None


class TestMedianInterval:
    def test_eleven_rounds_give_the_second_smallest_and_second_largest(self):
        # k = 2: misses with 2 * P(B(11, 1/2) <= 1) = 24/2048, 98.8 % coverage; k = 3 would be 93.5 %
        assert sb.median_interval([float(v) for v in (5, 3, 11, 1, 8, 2, 10, 4, 9, 7, 6)]) == (2.0, 10.0)

    def test_thirty_one_rounds_give_the_tenth_from_each_end(self):
        # k = 10: 2 * P(B(31, 1/2) <= 9) = 2.9 %; k = 11 would miss 7.1 % of the time
        assert sb.median_interval([float(v) for v in range(1, 32)]) == (10.0, 22.0)

    @pytest.mark.parametrize("n, expected", [(5, None), (6, (1.0, 6.0)), (8, (1.0, 8.0)), (9, (2.0, 8.0))])
    def test_the_interval_widens_to_the_extremes_and_then_gives_up(self, n, expected):
        # 6 values: 2/64 = 3.1 % miss at k = 1; 5 values: 2/32 = 6.25 %, not 95 % even at the extremes
        assert sb.median_interval([float(v) for v in range(1, n + 1)]) == expected

    def test_the_coverage_holds_whatever_the_distribution(self):
        rng = random.Random(7)
        misses = 0
        for _ in range(4000):  # a skewed distribution whose median is 1
            values = [rng.lognormvariate(0, 1) for _ in range(11)]
            lo, hi = sb.median_interval(values)
            misses += not lo <= 1 <= hi
        assert misses / 4000 < 0.05


@pytest.mark.parametrize("argv", [
    ["--sunflow-jar", "/no/such.jar"],
    ["--sunflow-jar", __file__, "--cases", "8spp"],
    ["--sunflow-jar", __file__, "--rounds", "0"],
    ["--sunflow-jar", __file__, "--no-launcher", "--no-jar"],
])
def test_bad_arguments_are_refused_before_anything_runs(argv, capsys):
    with pytest.raises(SystemExit) as e:
        sb.main(argv)
    assert e.value.code == 2


def test_the_sunflow_scene_has_the_ports_primitives():
    sc = sb.SCENE_SC.read_text()
    spheres = re.findall(r"type sphere\s+c (\S+ \S+ \S+)\s+r (\S+)", sc)
    assert len(spheres) == 8
    assert len(re.findall(r"type generic-mesh", sc)) == 64 and len(re.findall(r"triangles 2\n", sc)) == 64
    assert len(re.findall(r"type plane", sc)) == 1
    assert len(re.findall(r"^light \{", sc, re.MULTILINE)) == 3
    assert "resolution 600 600" in sc
    if sb.SCENE_XML.is_file():  # ../shared beside the project
        xml = sb.SCENE_XML.read_text()
        assert sorted(spheres) == sorted(re.findall(r'<sphere center="([^"]+)" radius="([^"]+)"', xml))
