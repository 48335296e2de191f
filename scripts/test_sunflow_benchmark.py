"""scripts/sunflow_benchmark.py without Sunflow or a JVM: command templates, the statistics read from
each side's output, the arguments refused, and that the Sunflow scene holds the port's primitives."""
from __future__ import annotations

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
