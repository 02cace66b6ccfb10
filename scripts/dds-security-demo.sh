#!/usr/bin/env bash
# Makes a throwaway DDS Security setup (identity and permissions CAs, one certificate per
# participant, signed governance and permissions documents, one Cyclone config per participant)
# and, with --run, shows a pool-server and a spectator talking through it while a spectator
# without credentials sees nothing. See docs/SECURITY.md. Not for production keys.
#   scripts/dds-security-demo.sh [--run] [OUTDIR]      (default OUTDIR: build/dds-security)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
run=0
if [[ ${1:-} == --run ]]; then run=1; shift; fi
out=$(realpath -m "${1:-$root/build/dds-security}")
mkdir -p "$out"
cd "$out"
plugins=${POOL_DDS_SECURITY_LIBS:-/usr/lib/x86_64-linux-gnu/libddsc0debian}
for lib in auth ac crypto; do
  [[ -f $plugins/libdds_security_$lib.so ]] || { echo "no $plugins/libdds_security_$lib.so" >&2; exit 1; }
done
subject() { echo "/C=NL/O=pool/CN=$1"; }
days=30

# 1. Two CAs: one vouches for identities, the other signs what each identity may do.
for ca in identity_ca permissions_ca; do
  openssl req -x509 -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes -days "$days" \
    -keyout "$ca.key" -out "$ca.pem" -subj "$(subject "pool $ca")" 2>/dev/null
done

# 2. One identity per participant role, signed by the identity CA.
roles=(server player)
for role in "${roles[@]}"; do
  openssl req -newkey ec -pkeyopt ec_paramgen_curve:prime256v1 -nodes \
    -keyout "$role.key" -out "$role.csr" -subj "$(subject "pool-$role")" 2>/dev/null
  openssl x509 -req -in "$role.csr" -CA identity_ca.pem -CAkey identity_ca.key -CAcreateserial \
    -days "$days" -out "$role.pem" 2>/dev/null
  rm "$role.csr"
done

# 3. Governance: nobody unauthenticated joins; discovery, liveliness, messages and data are
#    encrypted; every topic needs read and write permission.
cat > governance.xml <<'XML'
<?xml version="1.0" encoding="UTF-8"?>
<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance"
     xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_governance.xsd">
  <domain_access_rules>
    <domain_rule>
      <domains><id_range><min>0</min><max>230</max></id_range></domains>
      <allow_unauthenticated_participants>false</allow_unauthenticated_participants>
      <enable_join_access_control>true</enable_join_access_control>
      <discovery_protection_kind>ENCRYPT</discovery_protection_kind>
      <liveliness_protection_kind>ENCRYPT</liveliness_protection_kind>
      <rtps_protection_kind>ENCRYPT</rtps_protection_kind>
      <topic_access_rules>
        <topic_rule>
          <topic_expression>*</topic_expression>
          <enable_discovery_protection>true</enable_discovery_protection>
          <enable_liveliness_protection>true</enable_liveliness_protection>
          <enable_read_access_control>true</enable_read_access_control>
          <enable_write_access_control>true</enable_write_access_control>
          <metadata_protection_kind>ENCRYPT</metadata_protection_kind>
          <data_protection_kind>ENCRYPT</data_protection_kind>
        </topic_rule>
      </topic_access_rules>
    </domain_rule>
  </domain_access_rules>
</dds>
XML

# 4. Permissions: the server publishes what servers publish; players (spectators too: every
#    client session makes its command writer up front) send joins and commands.
topics() { for t in "$@"; do printf '<topic>pool/%s</topic>' "$t"; done; }
grant() {  # name, published topics, subscribed topics
  cat <<XML
    <grant name="$1">
      <subject_name>CN=pool-$1,O=pool,C=NL</subject_name>
      <validity><not_before>2020-01-01T00:00:00</not_before><not_after>2099-01-01T00:00:00</not_after></validity>
      <allow_rule>
        <domains><id_range><min>0</min><max>230</max></id_range></domains>
        <publish><topics>$2</topics></publish>
        <subscribe><topics>$3</topics></subscribe>
      </allow_rule>
      <default>DENY</default>
    </grant>
XML
}
server_out=$(topics MatchInfo JoinReply ShotResult TableSnapshot MatchState CueAim)
player_out=$(topics JoinRequest ShotCommand AimCommand)
{
  echo '<?xml version="1.0" encoding="UTF-8"?>'
  echo '<dds xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:noNamespaceSchemaLocation="http://www.omg.org/spec/DDS-SECURITY/20170901/omg_shared_ca_permissions.xsd">'
  echo '  <permissions>'
  grant server "$server_out" "$player_out"
  grant player "$player_out" "$server_out"
  echo '  </permissions>'
  echo '</dds>'
} > permissions.xml
for doc in governance permissions; do
  openssl smime -sign -in "$doc.xml" -text -out "$doc.p7s" \
    -signer permissions_ca.pem -inkey permissions_ca.key
done

# 5. One Cyclone config per role: the <Security> section of the domain (combine it with a
#    transport config, e.g. CYCLONEDDS_URI=file://assets/cyclone-lo.xml,file://OUT/server.xml).
for role in "${roles[@]}"; do
  cat > "$role.xml" <<XML
<?xml version="1.0" encoding="UTF-8" ?>
<CycloneDDS xmlns="https://cdds.io/config">
  <Domain Id="any">
    <Security>
      <Authentication>
        <Library path="$plugins/libdds_security_auth.so" initFunction="init_authentication"
                 finalizeFunction="finalize_authentication"/>
        <IdentityCA>file:$out/identity_ca.pem</IdentityCA>
        <IdentityCertificate>file:$out/$role.pem</IdentityCertificate>
        <PrivateKey>file:$out/$role.key</PrivateKey>
      </Authentication>
      <AccessControl>
        <Library path="$plugins/libdds_security_ac.so" initFunction="init_access_control"
                 finalizeFunction="finalize_access_control"/>
        <PermissionsCA>file:$out/permissions_ca.pem</PermissionsCA>
        <Governance>file:$out/governance.p7s</Governance>
        <Permissions>file:$out/permissions.p7s</Permissions>
      </AccessControl>
      <Cryptographic>
        <Library path="$plugins/libdds_security_crypto.so" initFunction="init_crypto"
                 finalizeFunction="finalize_crypto"/>
      </Cryptographic>
    </Security>
  </Domain>
</CycloneDDS>
XML
done
chmod 600 ./*.key
echo "DDS Security files in $out"
[[ $run == 1 ]] || exit 0

# 6. The demo, over loopback: a secured server, a secured spectator, an outsider.
bin=${POOL_BUILD_DIR:-$root/build}/bin
lo=file://$root/assets/cyclone-lo.xml
domain=${POOL_DOMAIN:-137}
CYCLONEDDS_URI="$lo,file://$out/server.xml" "$bin/pool-server" --domain "$domain" --tables 1 \
  --server-id demo --log-level warn &
server=$!
trap 'kill $server 2>/dev/null || true; wait 2>/dev/null || true' EXIT
seen=$(CYCLONEDDS_URI="$lo,file://$out/player.xml" timeout 20 "$bin/pool-client" \
  --domain "$domain" --spectate demo-1 --no-window --json --follow 2>/dev/null | head -n 1 || true)
outsider=$(CYCLONEDDS_URI="$lo" timeout 8 "$bin/pool-client" \
  --domain "$domain" --spectate demo-1 --no-window --json --follow 2>/dev/null | head -n 1 || true)
echo "secured spectator saw: ${seen:-nothing}"
echo "spectator without credentials saw: ${outsider:-nothing}"
[[ -n $seen && -z $outsider ]]
