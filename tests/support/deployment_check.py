#!/usr/bin/env python3
"""Checks docker/compose.yaml, docker/nginx.conf and docker/k8s/*.yaml against radiantd, where no
Docker engine or cluster runs: every radiantd flag and RADIANT_* variable they use exists in
`radiantd --help`; the replicas share one PostgreSQL store under distinct names; the proxy sends
to every replica; the Kubernetes probes, Secret, Service and ports agree; and each probe path
answers 200 on a running radiantd (--port), asked with the probe's own Host header; and each
platform waits longer after SIGTERM than radiantd drains (--drain-seconds) before it kills.

Usage: deployment_check.py --radiantd BIN --docker DIR --port PORT. Prints each problem; exit 1
if there is any."""
import argparse
import glob
import os
import re
import subprocess
import sys
import urllib.request

import yaml

problems = []


def check(condition, message):
    if not condition:
        problems.append(message)
    return condition


def radiantd_interface(binary):
    """radiantd's flags, its RADIANT_* variables, and its default --drain-seconds."""
    text = subprocess.run([binary, "--help"], capture_output=True, text=True, check=True).stdout
    drain = re.search(r"--drain-seconds [^\n]*?=([0-9.]+)", text)
    return (set(re.findall(r"(--[a-z][a-z-]*)", text)),
            set(re.findall(r"Env:(RADIANT_[A-Z_]+)", text)), float(drain.group(1)) if drain else 0)


def drain_seconds(default, args):
    """How long radiantd run with `args` drains after SIGTERM: the flag, else the default."""
    args = [str(a) for a in args or []]
    if "--drain-seconds" in args:
        return float(args[args.index("--drain-seconds") + 1])
    return default


def check_grace(where, grace_seconds, drain):
    """A platform that kills sooner than radiantd drains cuts a job's hand-back short."""
    check(grace_seconds is not None and grace_seconds > drain,
          f"{where}: waits {grace_seconds} s after SIGTERM, radiantd drains for {drain} s")


def check_arguments(where, args, flags):
    for arg in args or []:
        if str(arg).startswith("--"):
            check(str(arg).split("=")[0] in flags, f"{where}: radiantd has no flag {arg}")


def check_environment(where, names, variables):
    for name in names:
        if name.startswith("RADIANT_"):
            check(name in variables, f"{where}: radiantd reads no variable {name}")


def seconds(duration):
    """A compose duration ("30s", "1m30s") in seconds; None when missing."""
    if duration is None:
        return None
    parts = re.findall(r"([0-9.]+)(h|m|s|ms)", str(duration))
    return sum(float(n) * {"h": 3600, "m": 60, "s": 1, "ms": 0.001}[u] for n, u in parts)


def check_compose(docker, flags, variables, probes, drain):
    with open(os.path.join(docker, "compose.yaml")) as f:
        compose = yaml.safe_load(f)
    services = compose.get("services", {})
    replicas = {name: s for name, s in services.items() if s.get("image") == "radiant"}
    check(len(replicas) == 3, f"compose.yaml: {len(replicas)} radiantd replicas, not 3")
    names = set()
    for name, service in replicas.items():
        where = f"compose.yaml: {name}"
        environment = service.get("environment", {})
        check_environment(where, environment, variables)
        check_arguments(where, service.get("command"), flags)
        check_grace(where, seconds(service.get("stop_grace_period")),
                    drain_seconds(drain, service.get("command")))
        store = str(environment.get("RADIANT_STORE", ""))
        check(store.startswith("postgresql://") and "@postgres/" in store,
              f"{where}: RADIANT_STORE is not the postgres service's database: {store}")
        names.add(environment.get("RADIANT_REPLICA"))
        check("postgres" in service.get("depends_on", {}), f"{where}: does not wait for postgres")
        check(service.get("build", {}).get("dockerfile") == "docker/Dockerfile",
              f"{where}: not built from docker/Dockerfile")
        test = " ".join(service.get("healthcheck", {}).get("test", []))
        path = re.search(r"http://127\.0\.0\.1:8080(/\S*)", test)
        if check(path, f"{where}: its healthcheck asks no radiantd path: {test}"):
            probes.add((path.group(1), "127.0.0.1"))
    check(None not in names and len(names) == len(replicas),
          f"compose.yaml: replicas need distinct RADIANT_REPLICA names, not {sorted(map(str, names))}")
    check("postgres" in services, "compose.yaml: no postgres service")
    with open(os.path.join(docker, "nginx.conf")) as f:
        upstreams = set(re.findall(r"server\s+([\w-]+):8080", f.read()))
    check(upstreams == set(replicas),
          f"nginx.conf sends to {sorted(upstreams)}, the replicas are {sorted(replicas)}")


def check_kubernetes(docker, flags, variables, probes, drain):
    documents = []
    for path in sorted(glob.glob(os.path.join(docker, "k8s", "*.yaml"))):
        with open(path) as f:
            documents += [d for d in yaml.safe_load_all(f) if d]
    kinds = {}
    for d in documents:
        kinds.setdefault(d["kind"], []).append(d)
    missing = [kind for kind in ("Deployment", "Service", "Secret") if kind not in kinds]
    if not check(not missing, f"k8s: no {', '.join(missing)}"):
        return
    secrets = {s["metadata"]["name"]: s.get("stringData", {}) for s in kinds["Secret"]}
    deployment = kinds["Deployment"][0]
    labels = deployment["spec"]["template"]["metadata"]["labels"]
    check(deployment["spec"]["selector"]["matchLabels"] == labels,
          "k8s: the Deployment's selector does not match its pods' labels")
    container = deployment["spec"]["template"]["spec"]["containers"][0]
    check_arguments("k8s: radiantd", container.get("args"), flags)
    check_grace("k8s: the Deployment", deployment["spec"]["template"]["spec"].get(
        "terminationGracePeriodSeconds", 30), drain_seconds(drain, container.get("args")))
    environment = {e["name"]: e for e in container.get("env", [])}
    check_environment("k8s: radiantd", environment, variables)
    store = environment.get("RADIANT_STORE", {}).get("valueFrom", {}).get("secretKeyRef", {})
    check(store.get("key") in secrets.get(store.get("name"), {}),
          f"k8s: RADIANT_STORE comes from no key of a Secret: {store}")
    check("fieldRef" in environment.get("RADIANT_REPLICA", {}).get("valueFrom", {}),
          "k8s: each pod should name its replica after itself (RADIANT_REPLICA from a fieldRef)")
    listen = environment.get("RADIANT_LISTEN", {}).get("value", "")
    ports = {p.get("name"): p["containerPort"] for p in container.get("ports", [])}
    check(listen.endswith(":" + str(ports.get("http"))),
          f"k8s: radiantd listens on {listen}, the container port is {ports.get('http')}")
    for probe, want in (("livenessProbe", "/healthz"), ("readinessProbe", "/readyz")):
        get = container.get(probe, {}).get("httpGet", {})
        check(get.get("path") == want, f"k8s: the {probe} asks {get.get('path')}, not {want}")
        check(get.get("port") in ports, f"k8s: the {probe} port {get.get('port')} is no container port")
        host = {h["name"]: h["value"] for h in get.get("httpHeaders", [])}.get("Host")
        check(host is not None, f"k8s: the {probe} sends no Host radiantd answers to")
        probes.add((get.get("path"), host or "127.0.0.1"))
    for service in kinds["Service"]:
        check(service["spec"]["selector"] == labels, "k8s: the Service selects no radiantd pod")
        for port in service["spec"]["ports"]:
            check(port.get("targetPort") in ports,
                  f"k8s: the Service's targetPort {port.get('targetPort')} is no container port")
        allowed = environment.get("RADIANT_ALLOW_HOST", {}).get("value", "")
        check(allowed == service["metadata"]["name"],
              f"k8s: radiantd allows Host {allowed!r}, the Service is {service['metadata']['name']!r}")


def probe(port, probes):
    for path, host in sorted(probes):
        request = urllib.request.Request(f"http://127.0.0.1:{port}{path}", headers={"Host": host})
        try:
            with urllib.request.urlopen(request, timeout=10) as answer:
                status = answer.status
        except urllib.error.HTTPError as e:
            status = e.code
        check(status == 200, f"radiantd answers {status} to GET {path} (Host: {host}), not 200")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--radiantd", required=True)
    parser.add_argument("--docker", required=True)
    parser.add_argument("--port", required=True, type=int)
    args = parser.parse_args()
    flags, variables, drain = radiantd_interface(args.radiantd)
    probes = set()
    check_compose(args.docker, flags, variables, probes, drain)
    check_kubernetes(args.docker, flags, variables, probes, drain)
    probe(args.port, probes)
    for p in problems:
        print(p)
    if not problems:
        print(f"deployment files agree with radiantd; probes {sorted(probes)} answer 200")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
