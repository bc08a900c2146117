"""The scale-out recipes the README shows: the Kubernetes Indexed Job manifest parses as YAML and
asks for what tumble needs (Indexed completion, --shards equal to the completions, a trajectory,
no restarts in place), the Slurm script is valid bash, and the README shows both as they are in
docs/scale-out/. No cluster is needed: the manifest is checked by parsing.
Usage: check_manifests.py SOURCE_DIR. Exit 77 (skipped) without a YAML parser (python3-yaml)."""
import pathlib
import subprocess
import sys

try:
    import yaml
except ImportError:
    print("SKIPPED: no YAML parser for Python (apt-get install python3-yaml)")
    sys.exit(77)

source = pathlib.Path(sys.argv[1])
readme = (source / "README.md").read_text()
job_file = source / "docs/scale-out/render-job.yaml"
sbatch_file = source / "docs/scale-out/render.sbatch"
failures = []


def expect(ok, what):
    if not ok:
        failures.append(what)


def body(text):
    """The text from the first line that is not a plain comment (the README shows the file from there)."""
    lines = text.splitlines(keepends=True)
    start = next(i for i, l in enumerate(lines) if not (l.startswith("# ") or l.rstrip() in ("#", "") or l.startswith("#!")))
    return "".join(lines[start:])


job = yaml.safe_load(job_file.read_text())
spec = job["spec"]
expect(job["apiVersion"] == "batch/v1" and job["kind"] == "Job", "the manifest is not a batch/v1 Job")
expect(spec.get("completionMode") == "Indexed", "completionMode is not Indexed")
pod = spec["template"]["spec"]
expect(pod.get("restartPolicy") == "Never", "restartPolicy is not Never")
command = pod["containers"][0]["command"]
expect(command[:2] == ["tumble", "render"], "the container does not run 'tumble render'")
expect("--from-trajectory" in command, "the pods do not render from a trajectory")
shards = command[command.index("--shards") + 1] if "--shards" in command else None
expect(shards == str(spec["completions"]), f"--shards {shards} is not the Job's completions ({spec['completions']})")
expect("--frames" not in command and "--shard" not in command, "--frames or --shard would stop pods picking their chunk")

expect(body(job_file.read_text()) in readme, "README.md does not show docs/scale-out/render-job.yaml as it is")
expect(body(sbatch_file.read_text()) in readme, "README.md does not show docs/scale-out/render.sbatch as it is")
syntax = subprocess.run(["bash", "-n", str(sbatch_file)], capture_output=True, text=True)
expect(syntax.returncode == 0, "render.sbatch is not valid bash: " + syntax.stderr)

for f in failures:
    print("FAILED:", f)
if not failures:
    print("ok: the Indexed Job manifest and the Slurm script are well formed and shown in the README")
sys.exit(1 if failures else 0)
